// Parametric least-squares tensor-product B-spline surface with given parameters (Piegl & Tiller
// 2001, §2.3, §4; spec B2): x, y and z fitted at once (one factorisation, three right-hand sides),
// optionally with the boundary rows and columns fixed to four boundary curves, a given net size or
// refinement to a tolerance, and Hoschek parameter-correction rounds (every point re-projected on the
// current surface by local Newton, then refit; the best round is kept, never a worse one).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "src/nurbs/nurbs_surface.h"
#include "src/nurbs/patch_boundary.h"

namespace polarform {

struct SurfaceFitOptions {
  int degree_u = 3, degree_v = 3;
  // Control points per direction (> 0). With a fixed boundary 0 inherits the boundary curves'
  // counts (after degree elevation); without one 0 means 4 (or from the tolerance).
  int control_u = 0, control_v = 0;
  // > 0: knots are inserted (the midpoints of the spans holding points beyond the tolerance, worst
  // first, at most half the spans per step) until the max true distance of the points is <=
  // tolerance, max_control_points per direction is reached, or a further step would leave control
  // points without data (the last solvable net is kept; tolerance_met tells).
  double tolerance = 0.0;
  int max_control_points = 200;
  // Fix the first/last rows and columns to these curves: they are degree-elevated to the surface
  // degree and refined so that U holds the union of u0's and u1's knots (likewise V); rational
  // curves are refused.
  std::optional<PatchBoundary> boundary;
  // Parameter correction rounds after the first fit (0: none), over-relaxed (surface_fit.cpp);
  // rounds stop early when plain correction improves the max distance by less than 1 %.
  int correction_rounds = 0;
  // Weight of the thin-plate energy ∫∫ |S_uu|² + 2|S_uv|² + |S_vv|² added to the normal equations
  // (0: pure least squares); keeps an under-determined net well posed.
  double smoothing = 0.0;
  int threads = 2;
};

struct SurfaceFitRound {
  double max_distance = 0.0, rms_distance = 0.0;  // true distances of all points after the round
};

struct SurfaceFit {
  NurbsSurface surface;         // non-rational, domain [0, 1]²
  Eigen::VectorXd u, v;         // the parameters of the kept round (foot points on `surface`)
  Eigen::VectorXd distances;    // true distances |Q_k − S(u_k, v_k)| after projection
  double max_distance = 0.0, rms_distance = 0.0;
  std::vector<SurfaceFitRound> rounds;  // round 0 is the fit at the given parameters
  int best_round = 0;
  bool tolerance_met = true;    // max_distance <= tolerance (true without a tolerance)
};

// One least-squares solve at the given parameters with the options' net, degrees, boundary and
// smoothing (no tolerance loop, no correction, nothing measured): what fit_surface starts from.
NurbsSurface least_squares_surface(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u,
                                   const Eigen::VectorXd& v, const SurfaceFitOptions& options);

// points (3 × N), parameters u, v in [0, 1]. Throws InputError for mismatched sizes, parameters
// outside [0, 1], bad degrees/counts, or fewer points than free control points without smoothing.
SurfaceFit fit_surface(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u,
                       const Eigen::VectorXd& v, const SurfaceFitOptions& options);

}  // namespace polarform
