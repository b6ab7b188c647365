// The vessel job's figures: the curvature along the head (targets, achieved, the preset with its
// curvature jumps, and the residual at each target), the membrane stresses along the meridian with
// compressive hoop bands marked, and the head profile in the meridian section.
#pragma once

#include "export/svg_plot.h"
#include "jobs/vessel/vessel_job.h"

namespace polarform {

Figure curvature_figure(const VesselJobResult& r);
Figure stress_figure(const VesselJobResult& r);
Figure profile_figure(const VesselJobResult& r);

}  // namespace polarform
