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

// A roller of radius r is a pipe of radius r around the pitch curve, in the plane (MIT 13.472J
// §8.3.2-b, (8.45)–(8.46)): locally regular iff r < 1/κ_max, κ_max the largest |κ| of the pitch
// curve — unsigned, where min_convex_pitch_radius counts only the convex side, the one a roller
// undercuts; where the pitch curve is convex at its tightest bend the two are equal.
struct PitchPipeBound {
  double kappa_max = 0.0;  // 1/mm, max_curvature (src/nurbs/pipe_surface.h) of the pitch curve
  double r_local = 0.0;    // 1/κ_max, mm
};

// The pitch curve as the cubic spline through its points at `samples` equally spaced cam angles
// and the segment boundaries (parameter θ, one tangent at the seam, the exact one), and the pipe
// code's exact κ_max of it (root isolation of (κ²)′ on its Bézier pieces). At 36 000 samples
// (0.01°) its κ_max is the pitch curve's to about 1e-7 relative (measured on a steep short rise
// at a small base radius; 1e-5 at 7200 samples).
PitchPipeBound pitch_pipe_bound(const PlateCam& cam, int samples = 36000);

// `count` equally spaced angles k 2π / count, k = 0..count-1.
std::vector<double> uniform_angles(int count);

// Both take increasing angles in [0, 2π] (at least 2); InputError otherwise.
MotionExtrema motion_extrema(const CamProgram& program, std::span<const double> thetas);
CamAnalysis analyse(const PlateCam& cam, std::span<const double> thetas);

}  // namespace polarform
