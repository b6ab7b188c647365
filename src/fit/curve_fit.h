// Parametric least-squares B-spline curve fit, 2D or 3D (MIT 13.472J §8.1, eqs. (8.1)–(8.11)):
// chord-length parameters, knots at equal counts of parameters (NURBS Book eqs. (9.68)–(9.69)),
// corner knots of multiplicity p (C0), fixed end points moved to the right-hand side (8.5), open or
// closed (periodic knots, Bae 2002 (3.9)–(3.10)), and knot insertion where the measured true
// distance exceeds a tolerance. Shared by sweep recovery (Kantz 2003) and surface patches.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "src/nurbs/nurbs_curve.h"

namespace polarform {

template <int Dim>
struct CurveFitOptions {
  using Point = Eigen::Matrix<double, Dim, 1>;
  int degree = 3;
  // Closed: the curve returns to its start. Smooth closed curves get periodic knots (C^{p-1} at
  // the seam); with corners the curve starts and ends at the first corner (C0 there).
  bool closed = false;
  // Indices into the points at (or next to) which the curve turns sharply: a knot of multiplicity
  // `degree` there (MIT §8.1, Note 1). Need not be sorted.
  std::vector<int> corners;
  // Each corner is placed where the regression lines of up to this many points on either side
  // meet, and the curve interpolates it (its control point is fixed there).
  int corner_support = 5;
  // Open curves: the end control points are fixed to these (MIT eq. (8.5)); fix_ends fixes them
  // to the first and last data points.
  bool fix_ends = false;
  std::optional<Point> start, end;
  // > 0: exactly this many distinct control points (no tolerance loop).
  int control_points = 0;
  // Else knots are inserted until the max true distance <= tolerance, or until max_control_points.
  double tolerance = 0.0;
  int max_control_points = 2000;
  // Per-point weights (empty: all 1) and given parameters in [0, 1] (empty: chord length).
  Eigen::VectorXd weights;
  Eigen::VectorXd parameters;
  // Rounds of parameter correction (Hoschek: points re-projected, then refit); the best round kept.
  int correction_rounds = 2;
};

template <int Dim>
struct CurveFit {
  NurbsCurve<Dim> curve;       // non-rational, domain [0, 1]
  Eigen::VectorXd parameters;  // the parameters of the points in the final solve
  Eigen::VectorXd distances;   // true distances of the points to the curve
  double max_distance = 0.0;
  double rms = 0.0;
  bool tolerance_met = false;  // max_distance <= tolerance (true when no tolerance was asked)
  std::vector<double> corner_parameters;  // where the C0 knots are (0: a closed curve's C0 seam)
};

// Chord-length parameters of ordered points (MIT eqs. (8.1)–(8.3)) normalised to [0, 1]; closed
// curves count the closing chord, so the last point's parameter is < 1. Coincident points share a
// parameter; all-coincident points get uniform parameters.
template <int Dim>
Eigen::VectorXd chord_length_parameters(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& points,
                                        bool closed);

// Fits the ordered columns of `points` (at least degree + 1 of them, open; 3 closed). Throws
// InputError on bad options or too few points.
template <int Dim>
CurveFit<Dim> fit_curve(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& points,
                        const CurveFitOptions<Dim>& options);

}  // namespace polarform
