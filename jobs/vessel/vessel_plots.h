// The vessel job's figures, built from its stages so that the studio shows them while a solve is
// converted (or after a conversion failed): the curvature along the head (targets, achieved, the
// preset with its curvature jumps, and the residual at each target), the membrane stresses along
// the meridian with compressive hoop bands marked, a minimum-stress head against the standard heads
// of its depth, and the head profile in the meridian section.
#pragma once

#include "export/figure.h"
#include "jobs/vessel/vessel_job.h"

namespace polarform {

Figure curvature_figure(const VesselSolveStage& solved);
Figure stress_figure(const VesselSolveStage& solved);
// A minimum-stress head's hoop and meridional stresses against θ beside the standard heads of its
// depth (needs solved.solution.minimum_stress).
Figure same_depth_figure(const VesselSolveStage& solved);
// The NURBS profile with its control polygon when converted, else the synthesised R(θ).
Figure profile_figure(const VesselSolveStage& solved, const VesselConversionStage* converted);

}  // namespace polarform
