// Analyses of a plate cam on a user-chosen grid of cam angles: SVAJ extremes, pressure angle,
// radii of curvature of pitch curve and contour, undercut ranges and the flat face's width.
// Every extreme is located on the grid and then refined by Brent's method between the
// neighbouring grid angles (segment by segment, so one-sided values at boundaries count), so the
// reported values are the functions' extremes, not the samples'. Norton, Cam Design and Manufacturing Handbook (cam sizing).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "designers/cam/extremum_search.h"
#include "designers/cam/plate_cam.h"

namespace polarform {

struct AngleRange {
  double from = 0.0;  // rad
  double to = 0.0;
};

// Contact extents on a flat face (CamSample::face_contact, mm): the face needs at least
// [left, right] plus clearance.
struct FaceWidth {
  double left = 0.0;
  double right = 0.0;
  double width() const { return right - left; }
};

// Largest |s'|, |s''|, |s'''| (mm/rad^k) and where they occur.
struct MotionExtrema {
  Extremum velocity;
  Extremum acceleration;
  Extremum jerk;
};

struct CamAnalysis {
  std::vector<CamSample> samples;  // one per grid angle
  MotionExtrema motion;
  Extremum max_pressure_angle;         // largest |φ|, rad (0 for a flat face)
  Extremum min_convex_pitch_radius;    // smallest positive radius of curvature; +inf if none
  Extremum min_convex_contour_radius;  // smallest positive radius of curvature; +inf if none
  Extremum min_concave_contour_radius; // smallest |ρ| where concave; +inf if none
  Extremum min_contour_speed;          // CamSample::contour_speed; <= 0 means undercut
  std::vector<AngleRange> undercut;    // θ ranges with contour_speed <= 0, ends bisected
  std::optional<FaceWidth> face_width; // flat-faced followers
};

// `count` equally spaced angles k 2π / count, k = 0..count-1.
std::vector<double> uniform_angles(int count);

// Both take increasing angles in [0, 2π] (at least 2); InputError otherwise.
MotionExtrema motion_extrema(const CamProgram& program, std::span<const double> thetas);
CamAnalysis analyse(const PlateCam& cam, std::span<const double> thetas);

}  // namespace polarform
