// The symbolic product of B-splines (Bae 2002, Appendix A.1/A.2/B.1; Piegl & Tiller, CAD 1997;
// knot rule after Mørken 1991) and the polar, spherical and cylindrical NURBS built with it:
// C^w = (F·X^w, F·Y^w, W) (A.2), S^w = (F·X^w, F·Y^w, F·Z^w, W) (B.2), (F·X^w, F·Y^w, Z^w, W) (B.3).
// Both factors are Bezier-decomposed on the union of their breaks, multiplied piece by piece,
// recomposed, and exactly the knots not in (A.7) removed.
#pragma once

#include <vector>

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// The knot vector of the product of degree p + q (Bae 2002, eq. (A.7)): an interior knot of
// multiplicity m in one factor gets m + (degree of the other factor), the larger where both have
// it; clamped ends of multiplicity p + q + 1. Throws InputError if the domains differ or an
// interior knot has multiplicity above its factor's degree (a discontinuous factor).
Knots product_knots(int p, const Knots& U, int q, const Knots& V);

// U with every knot that lies within a rounding error (1e-12 of the domain) of one of V's values
// moved onto it: a factor's knot meant to fall on the other's break (an F knot on a base-arc
// joint) must not become a second break an ulp away, which would make two knots of the product
// whose multiplicities together exceed its degree + 1.
Knots snap_knots(const Knots& U, const Knots& V);

// H = f·g of degree p + q on product_knots (the first factor's knots snapped to the second's). f
// scalar (dim 1) multiplies every row of g; otherwise f.dim() == g.dim() and the rows multiply
// pairwise. removal_tol > 0 then removes whatever else is removable within that coefficient-space
// tolerance (NURBS Book A5.8). Throws NumericalError if a knot that (A.7) drops does not come out
// at round-off.
BSpline product(const BSpline& f, const BSpline& g, double removal_tol = 0.0);

// Row products: row r of the result is row factor_rows[r] of `factors` times row g_rows[r] of g,
// e.g. factors = common_basis({Rc, z0 + S, 1}), factor_rows {0, 0, 1, 2}, g a circle
// (X^w, Y^w, W), g_rows {0, 1, 2, 2} gives the cylindrical-cam track (Rc·X^w, Rc·Y^w, (z0+S)·W, W).
BSpline product_rows(const BSpline& factors, const std::vector<int>& factor_rows, const BSpline& g,
                     const std::vector<int>& g_rows, double removal_tol = 0.0);

// The bivariate product (Bae 2002, eq. (B.6)), the same rules per direction; removal_tol applies to
// every control point of the net.
BSplineSurface product(const BSplineSurface& f, const BSplineSurface& g, double removal_tol = 0.0);
BSplineSurface product_rows(const BSplineSurface& factors, const std::vector<int>& factor_rows,
                            const BSplineSurface& g, const std::vector<int>& g_rows,
                            double removal_tol = 0.0);

// C = F·B as a NURBS curve (Bae 2002, eq. (A.2)): C^w = (F·X^w, F·Y^w[, F·Z^w], 1·W) with the 1
// written in F's basis, so all rows share degree p + q and the knots (A.7). removal_tol is a
// Cartesian distance, converted with homogeneous_tolerance (NURBS Book eq. (5.30)).
template <int D>
NurbsCurve<D> product(const BSplineFunction& F, const NurbsCurve<D>& B, double removal_tol = 0.0);

// S = F·B over a base sphere (Bae 2002, eq. (B.2)); degrees (p + 2, q + 2) for a (2, 2) base.
NurbsSurface product(const BSplineSurface& F, const NurbsSurface& B, double removal_tol = 0.0);

// S = (F·X, F·Y, Z) over a base cylinder (Bae 2002, eq. (B.3)); degrees (max(p, 1), q + 2) for a
// (1, 2) base (B.8). B must be a cylinder along u: X^w, Y^w and W constant along u and
// Z^w = z(u)·W(v); otherwise InputError.
NurbsSurface cylindrical_product(const BSplineSurface& F, const NurbsSurface& B,
                                 double removal_tol = 0.0);

}  // namespace polarform
