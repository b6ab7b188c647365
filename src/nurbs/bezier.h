// Bezier decomposition and recomposition: a B-spline as its polynomial pieces (NURBS Book A5.6,
// by knot refinement to multiplicity p at every break) and back (the full-multiplicity knot vector,
// exactly). bezier_stack is the one-allocation form the symbolic product works on, on a chosen set
// of breaks that may be finer than the B-spline's own knots.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

struct BezierSegments {
  int degree;
  std::vector<double> breaks;             // b_0 < ... < b_k: segment i lives on [b_i, b_{i+1}]
  std::vector<Eigen::MatrixXd> segments;  // k matrices of dim x (degree + 1) Bezier coefficients
};

// The Bezier pieces of c on its domain between its distinct knots. Works on clamped and unclamped
// knot vectors.
BezierSegments decompose_bezier(const BSpline& c);

// The B-spline of the pieces: ends of multiplicity p+1, each interior break of multiplicity p where
// the neighbouring pieces share their end coefficient exactly (their common column is kept) and
// p+1 where they do not (both are kept). Exact: no coefficient is recomputed. Throws InputError on
// malformed segments.
BSpline compose_bezier(const BezierSegments& bezier);

// The Bezier coefficients of c on the pieces between `breaks` (strictly increasing, from front to
// back, containing every interior knot of c), stacked: piece i in columns i(p+1) .. i(p+1)+p.
Eigen::MatrixXd bezier_stack(const BSpline& c, const std::vector<double>& breaks);

// The same for a surface on a grid of breaks: coefficient (i, j) of patch (a, b), component k, at
// row (a(p_u+1) + i)·dim + k and column b(p_v+1) + j.
Eigen::MatrixXd bezier_stack(const BSplineSurface& s, const std::vector<double>& ubreaks,
                             const std::vector<double>& vbreaks);

}  // namespace polarform
