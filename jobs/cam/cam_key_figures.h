// What a cam engineer reads first, in one place for report.html (its first table), the CLI's
// summary and the studio: the design inputs (cam, follower, geometry, speed, every segment) and
// the key results (peak velocity, acceleration and jerk in time units at the cam's speed and per
// radian, the smallest radii of curvature of pitch curve and contour, the largest pressure angle
// with its limit, and the exact profile's size and measured error).
#pragma once

#include <string>
#include <vector>

#include "jobs/cam/cam_job.h"

namespace polarform {

struct KeyFigure {
  std::string name;   // "peak acceleration"
  std::string value;  // "31.6 m/s² (351 mm/rad²) at θ = 101°"
};

// The design as the project states it: one line for the cam and follower, one per segment.
std::vector<KeyFigure> cam_design_inputs(const CamDesignStage& design);

// The follower dynamics' lines: least contact force and the jump speed, the least spring (torsion)
// rate that keeps contact, the largest camshaft torque and contact stress.
std::vector<KeyFigure> cam_dynamics_figures(const FollowerDynamics& dynamics,
                                            const FollowerLoad& load);

// The results; the profile's lines only with a conversion.
std::vector<KeyFigure> cam_key_results(const CamDesignStage& design,
                                       const CamAnalysisStage& analysis,
                                       const CamConversionStage* conversion);

}  // namespace polarform
