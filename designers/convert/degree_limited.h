// Degree-limited profiles for consumers that cap the spline degree (AutoCAD's DXF reader at 10,
// many CAM systems at 3): a non-rational B-spline of the requested degree that approximates the
// polar curve r = R(ψ) within the tolerance, with the error measured on the result. Also the
// baseline a CAD user would otherwise build: a spline interpolating points sampled from the exact
// profile, as many as needed.
#pragma once

#include <stop_token>
#include <vector>

#include "designers/convert/polar_function.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

// How much work the fit spends for fewer control points: the density table of R, the rounds of
// knot placement, the Lawson steps of each minimax fit and the knot removals tried. The defaults
// are the degree-limited export's; the converter's refit (polar_conversion.h) runs leaner.
struct LimitedEffort {
  int table_intervals = 4096;  // ProfileTable's
  // Rounds of knot placement on plain fits (one solve each): the equidistribution wanders rather
  // than converges and the best round is kept; at degree 3 on the 66 peer_counts rows, 30 rounds
  // give 1971 control points in all against 2022 with 10.
  int placement_rounds = 30;
  int lawson_steps = 8;  // of each minimax fit (more gain little)
  // Knot removals tried by refit, the most removable first (the converter's refit tries 8:
  // polar_conversion.cpp gives what that costs).
  std::size_t removal_tries = 20;
  // fewest_control_points: how many degrees are fitted to the end (those whose placement predicts
  // the fewest control points; a degree that fails makes way for the next).
  std::size_t finalists = 1;
  // The verification of step 4 against the table of R instead of R itself (far cheaper where R
  // is costly to evaluate), for a caller that measures the result against R again.
  bool verify_on_table = false;
};

struct LimitedCurve {
  NurbsCurve2d curve;           // clamped; closed when R is (C^{p-1} at the seam, or as R there)
  double max_radial_error = 0;  // mm, measured against R (or its table: verify_on_table)
  double max_normal_error = 0;  // mm
  int control_points = 0;
};

// A tolerance-driven least-squares B-spline with knots placed by need (periodic when R is closed,
// C^{p-1} across the seam, or C^{k-1} where R's derivative of order k <= 4 jumps there; an open
// one keeps R's end points): knots equidistributing the measured error (de Boor), a knot wherever
// a derivative of order k <= min(p, 4) of R jumps (of multiplicity p − (k − 1): C^(k−1) there, as
// R is), the fewest spans on that density whose minimax fit meets tol, knot removal by refit,
// then the result measured against R itself (a span split where it misses). The fits let the curve
// slide along the profile and are pushed toward the minimax radial error (profile_fit.h). A
// mirror-symmetric R (polar_function.h) is fitted as its own mirror image (Mirror::at_end on its
// first half). Throws NumericalError if 20000 spans do not reach tol.
LimitedCurve approximate_polar_curve(const PolarFunction& R, int degree, double tol,
                                     const LimitedEffort& effort = {});

// Whether R over [a, m] is the first half of a profile that is its own mirror image in the line
// θ = m (a vessel head's meridian over [0, π/2], mirrored in the head's axis): the curve then
// covers the whole profile over [a, 2m − a], its control values tied in mirror pairs (a simple
// knot at m, or none), and is fitted and measured on [a, m].
enum class Mirror { none, at_end };

// The degree-limited fit at the best of `degrees` on one table of R: every degree's knots placed by
// need, then fitted to the end in the order of the control points the placements predict (each
// placement's minimax fit on its spans, scaled as if its error went like h^(p+1)) until
// `effort.finalists` have met the tolerance and no degree left predicts fewer control points than
// the best of them, and the verified curve with the fewest control points kept (the lower degree
// among equals). The degrees' placements and the finalists' fits are tasks of their own
// (task_pool.h), and each knot-removal try has the next one run beside it (kept only if it fails:
// the result is the same as one try at a time); R's derivatives must be safe to call concurrently
// (every PolarFunction's are: pure functions of immutable data). Throws NumericalError when every
// degree fails, or when `stop` is requested (between two fits).
LimitedCurve fewest_control_points(const PolarFunction& R, const std::vector<int>& degrees,
                                   double tol, const LimitedEffort& effort = {},
                                   std::stop_token stop = {}, Mirror mirror = Mirror::none);

// Interpolation of N points R(ψ_k)(cos ψ_k, sin ψ_k) equally spaced in ψ, with the fewest N (found
// by bisection) whose measured radial error meets tol: the usual "spline through points" export.
LimitedCurve interpolate_polar_curve(const PolarFunction& R, int degree, double tol);

}  // namespace polarform
