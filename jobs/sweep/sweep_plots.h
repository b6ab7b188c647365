// The figures of a sweep job: the meridian profile (the projected points, the profile points it
// was fitted to, its corners and the curve; z along the axis, r from it) and the preview (the
// signed deviation of every point against z).
#pragma once

#include "export/figure.h"
#include "jobs/sweep/sweep_job.h"

namespace polarform {

Figure sweep_profile_figure(const SweepJobResult& r);
Figure sweep_preview_figure(const SweepJobResult& r);

}  // namespace polarform
