// The boundary of a scanned patch from what users have (Piegl & Tiller 2001, §2 takes four curves
// as given): four polylines in loop order, oriented by their end points, their shared corners
// snapped, each fitted by a parametric least-squares B-spline (spec B1) with its ends fixed at the
// corners; or a structured grid (row-major rows × cols, e.g. a range scan), whose border rows and
// columns are the four polylines and whose inside is the data.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "src/nurbs/patch_boundary.h"

namespace polarform {

struct BoundaryFitOptions {
  int degree = 3;
  // The max distance of a polyline's points to its curve; the fit stops earlier at the noise
  // floor: max(tolerance, 4·σ̂) with σ̂ the polyline's third-difference noise estimate, and at one
  // control point per 4 points.
  double tolerance = 0.0;  // <= 0: 1e-5 of the boundary's size
  // Ends of consecutive polylines farther apart than this are refused (<= 0: 1 % of the size).
  double corner_tolerance = 0.0;
};

struct FittedBoundary {
  PatchBoundary boundary;
  // Per polyline in file (loop) order:
  std::array<bool, 4> reversed{};        // run backwards to continue the loop
  std::array<double, 4> corner_gap{};    // mm between the previous curve's end and this one's start
  std::array<double, 4> max_distance{};  // of its points to its fitted curve
  std::array<double, 4> noise{};         // σ̂ (mm)
  std::array<int, 4> control_points{};
  double tolerance = 0.0, corner_tolerance = 0.0;  // as used (mm)
};

// Throws InputError naming the corner (where curve k starts) and its gap when the polylines do not
// form a loop, or for a polyline of fewer than 2 points.
FittedBoundary fit_boundary_polylines(const std::array<Eigen::Matrix3Xd, 4>& polylines,
                                      const BoundaryFitOptions& options = {});

// A structured grid split into its border and inside: point (r, c) is column r·cols + c; u runs
// along c, v along r. polylines: row 0, column cols−1, row rows−1 backwards, column 0 backwards.
struct StructuredGrid {
  std::array<Eigen::Matrix3Xd, 4> polylines;
  std::vector<int> inside;  // indices of the points not on the border, increasing
};
// Throws InputError unless rows, cols >= 3 and rows·cols equals the number of points.
StructuredGrid split_structured_grid(const Eigen::Matrix3Xd& points, int rows, int cols);

}  // namespace polarform
