// Everything the cam workspace shows about a design, computed by the cam designer: the program,
// the plate or barrel cam, motion curves sampled segment by segment (one-sided values at the
// boundaries, so jumps show as jumps), the profile curves with pressure angle and curvature, the
// analysis extremes and the continuity diagnostics. Throws InputError for an invalid design.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "designers/cam/cam_analysis.h"
#include "designers/cam/cam_design.h"
#include "designers/cam/continuity.h"

namespace polarform::studio {

struct MotionCurves {
  std::vector<double> theta_deg;     // cam angle, degrees
  std::vector<double> s, v, a, j;    // mm, mm/rad, mm/rad², mm/rad³
  std::vector<double> pressure_deg;  // pressure angle, degrees (plate cams; barrel: at Rc)
};

struct ProfileCurves {  // cam frame, mm; one entry per sample of MotionCurves
  std::vector<Eigen::Vector2d> pitch, contour, normal;  // normal: unit, pointing out of the cam
  std::vector<double> theta;                            // cam angle, rad
  std::vector<double> pressure;                         // rad
  std::vector<double> curvature;  // signed contour curvature, 1/mm (> 0 convex)
};

struct CamResults {
  CamDesign design;
  std::optional<CamProgram> program;
  std::optional<PlateCam> plate;    // plate cams
  std::optional<BarrelCam> barrel;  // cylindrical cams
  MotionCurves motion;
  ProfileCurves profile;                // plate cams
  std::optional<CamAnalysis> analysis;  // plate cams: extremes (samples dropped)
  MotionExtrema extrema;
  std::vector<ContinuityIssue> issues;  // up to jerk
  std::vector<double> boundaries_deg;   // segment starts after the first, degrees
};

// Samples per revolution of the motion and profile curves.
inline constexpr int kCamSamples = 720;

CamResults compute_cam_results(const CamDesign& design, int samples = kCamSamples);

}  // namespace polarform::studio
