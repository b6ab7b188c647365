// Knot removal (NURBS Book A5.8): drop an interior knot as often as the B-spline allows within a
// tolerance in coefficient space (for a NURBS: on the homogeneous coefficients;
// homogeneous_tolerance converts a Cartesian tolerance, eq. (5.30)). A removal's deviation is the
// residual of the removal equation left unsolved; the B-spline moves by at most that. Surfaces
// remove along one direction, the tolerance applying to every control point of the net.
#pragma once

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

struct KnotRemoval {
  BSpline spline;
  int removed;  // how many of the requested removals were made
};

struct SurfaceKnotRemoval {
  BSplineSurface surface;
  int removed;
};

// Removes the interior knot u up to `times` times (1 <= times <= its multiplicity), stopping at
// the first removal whose deviation exceeds tol (>= 0). Throws InputError if u
// is not an interior knot or times is out of range.
KnotRemoval remove_knot(const BSpline& c, double u, int times, double tol);
SurfaceKnotRemoval remove_knot_u(const BSplineSurface& s, double u, int times, double tol);
SurfaceKnotRemoval remove_knot_v(const BSplineSurface& s, double v, int times, double tol);

// Farin's least-squares removal of a simple interior knot (MIT 13.472J §8.2.3-2, eqs.
// (8.24)–(8.28)): the p − 1 control points P_{r−p}..P_{r−2} of the spline without u = U[r] that
// best reproduce the original ones under re-insertion of u (the p equations
// α_i P_i + (1 − α_i) P_{i−1} = Q_i, i = r−p..r−1), always solved, never refused. `bound` is
// max_i |R_i − Q_i| over the control points of the re-inserted spline R (eqs. (8.34)–(8.36)): by
// the partition of unity the curve moves by at most that. Throws InputError unless u is a simple
// interior knot. point_dim (> 0, dividing dim; 0: dim) splits each coefficient column into points
// of that many rows — a surface net viewed along one direction — and the bound is per point.
struct LeastSquaresRemoval {
  BSpline spline;  // without u
  double bound;
};
LeastSquaresRemoval remove_knot_least_squares(const BSpline& c, double u, int point_dim = 0);

// Coefficient-space tolerance that keeps a rational curve within the Cartesian tolerance tol:
// tol · w_min / (1 + |P|_max) over the control points P and weights w (NURBS Book eq. (5.30)).
// `homogeneous` is the homogeneous B-spline (last row the weights, all > 0).
double homogeneous_tolerance(const BSpline& homogeneous, double tol);
double homogeneous_tolerance(const BSplineSurface& homogeneous, double tol);

// Every interior knot removed as often as it can go within tol, left to right. Each removal is
// checked on its own, so the deviations of successive removals can add up.
BSpline remove_removable_knots(const BSpline& c, double tol);
BSplineSurface remove_removable_knots_u(const BSplineSurface& s, double tol);
BSplineSurface remove_removable_knots_v(const BSplineSurface& s, double tol);

}  // namespace polarform
