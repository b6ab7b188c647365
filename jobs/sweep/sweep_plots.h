// The figures of a sweep job: the profile in its plane (the projected points, the profile points
// it was fitted to, its corners and the curve; the meridian (z, r) of a surface of revolution or
// the section (x, y) of an extrusion) and the preview (the signed deviation of every point against
// z along the axis, or against its angle about the section's centroid).
#pragma once

#include "export/figure.h"
#include "jobs/sweep/sweep_job.h"

namespace polarform {

Figure sweep_profile_figure(const SweepJobResult& r);
Figure sweep_preview_figure(const SweepJobResult& r);

}  // namespace polarform
