// Local fairing of B-spline curves (Patrikalakis & Maekawa, MIT 13.472J lecture 8, §8.2.3): the
// fairness measure is the jump of the p-th derivative at each interior knot (8.13); Kjellander's
// method moves the data point at the worst jump onto the Hermite cubic of its neighbours and
// re-interpolates (8.15)–(8.18); Farin's removes the worst knot by least squares and re-inserts it
// (8.19)–(8.33), which makes the curve C^∞ there and moves only p control points. Both work on
// B-splines of any dimension (a profile's coordinates or a scalar F(θ)); Farin's also along one
// direction of a surface net (all rows at once).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"
#include "src/nurbs/curve_interpolation.h"

namespace polarform {

struct SplineKnotJump {
  double u;
  double jump;  // |C^(p)(u+) − C^(p)(u−)| (Euclidean over the coefficient rows)
};

// The jump of the p-th derivative at every distinct interior knot, in order (exact: the p-th
// derivative is piecewise constant; NURBS Book A3.3 applied p times).
std::vector<SplineKnotJump> top_derivative_jumps(const BSpline& c);
// The largest of them (0 without interior knots).
double max_top_derivative_jump(const BSpline& c);

struct FairingStep {
  double u;  // the knot faired (Kjellander: the data parameter)
  double jump_before, jump_after;
  double bound;  // Farin: max control-point move (8.36); Kjellander: the data move
};

struct FairingOptions {
  double tolerance = 0.0;  // the total deviation allowed: summed bounds (Farin), data moves
                           // from the original (Kjellander); <= 0 refuses
  int max_passes = 100;
  // A knot whose jump is at most this fraction of the largest initial jump is fair already.
  double negligible_jump = 1e-9;
  // Farin: this many control points at each end never move (a closed curve keeps its seam
  // C^{p−1} with `degree` of them); knots whose removal would move them are left alone.
  int fixed_end_points = 0;
};

struct CurveFairing {
  BSpline spline;
  std::vector<FairingStep> steps;
  double total_bound = 0.0;  // Farin: Σ bounds, an upper bound of the curve's move
};

// Farin (M4): repeatedly the simple interior knot with the largest jump whose least-squares
// removal and re-insertion keeps the summed bounds within the tolerance (knots that would exceed
// it are skipped); stops when no knot can be faired, every jump is negligible, or after
// max_passes. Multiple knots (corners, C0 seams) are left alone. point_dim as for
// remove_knot_least_squares (the bound per point of that many coefficient rows).
CurveFairing farin_fair(const BSpline& c, const FairingOptions& options, int point_dim = 0);

struct KjellanderFairing {
  BSpline spline;          // the final interpolant
  Eigen::MatrixXd values;  // the faired data
  std::vector<FairingStep> steps;
  double max_data_move = 0.0;  // max over points of |P_new − P_original|
};

// Kjellander (M3): values (dim × N, N >= 5) interpolated by a natural cubic at the parameters;
// each pass takes the interior data point at the largest third-derivative jump, replaces it by the
// Hermite cubic of its neighbours (their values and the interpolant's tangents) evaluated at its
// parameter, and re-interpolates; a pass that would move a point beyond the tolerance from its
// original position ends the loop, as does a negligible jump or max_passes.
// `ends` gives the interpolant's end tangents (natural ends where absent).
KjellanderFairing kjellander_fair(const Eigen::MatrixXd& values, const Eigen::VectorXd& parameters,
                                  const FairingOptions& options, const CubicEnds& ends = {});

// Kjellander on a cubic B-spline (any dimension): its values at its distinct breakpoints are the
// data, its end tangents kept (so a closed curve stays C1 at its seam); total_bound is the largest
// data move. Fewer than 5 breakpoints leave it as it is. Throws InputError for a degree other
// than 3 or a multiple interior knot.
CurveFairing kjellander_fair_spline(const BSpline& c, const FairingOptions& options);

struct SurfaceFairing {
  BSplineSurface surface;
  std::vector<FairingStep> steps;  // along u: knots of u; along v: knots of v
  double total_bound = 0.0;
};

// Farin along u (every row of the net at once: one knot, common α) or along v (MIT §8.2.4).
SurfaceFairing farin_fair_surface_u(const BSplineSurface& s, const FairingOptions& options);
SurfaceFairing farin_fair_surface_v(const BSplineSurface& s, const FairingOptions& options);

}  // namespace polarform
