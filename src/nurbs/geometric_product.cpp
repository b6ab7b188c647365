// The geometric half of symbolic_product.h: NURBS curves and surfaces built as a scalar B-spline F
// times a base circle, sphere or cylinder in homogeneous form (Bae 2002, eqs. (A.2), (B.2), (B.3)).
#include <cmath>
#include <numeric>
#include <string>

#include "src/error.h"
#include "src/nurbs/common_basis.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_removal.h"
#include "src/nurbs/symbolic_product.h"

namespace polarform {

namespace {

std::vector<int> iota_rows(int n) {
  std::vector<int> rows(n);
  std::iota(rows.begin(), rows.end(), 0);
  return rows;
}

// F and the constant 1 in F's basis (partition of unity) as the two rows of one B-spline surface.
BSplineSurface with_one(const BSplineSurface& F) {
  Eigen::MatrixXd c(2, F.coefs().cols());
  c.row(0) = F.coefs().row(0);
  c.row(1).setOnes();
  return BSplineSurface(F.degree_u(), F.degree_v(), F.knots_u(), F.knots_v(), std::move(c));
}

void check_scalar(const BSplineSurface& F, const char* what) {
  if (F.dim() != 1)
    throw InputError(std::string(what) + ": F has dimension " + std::to_string(F.dim()) +
                     ", expected a scalar function (1)");
}

void check_removal_tol(double tol, const char* what) {
  if (!(tol >= 0.0) || !std::isfinite(tol))
    throw InputError(std::string(what) + ": removal_tol is " + to_text(tol) +
                     ", expected a finite Cartesian distance >= 0");
}

NurbsSurface finish(BSplineSurface h, double removal_tol) {
  if (removal_tol > 0.0) {
    const double tol = homogeneous_tolerance(h, removal_tol);
    h = remove_removable_knots_v(remove_removable_knots_u(h, tol), tol);
  }
  return NurbsSurface(std::move(h));
}

}  // namespace

// Bae 2002, eq. (A.2).
template <int D>
NurbsCurve<D> product(const BSplineFunction& F, const NurbsCurve<D>& B, double removal_tol) {
  check_removal_tol(removal_tol, "curve product");
  const BSpline& f = F.spline();
  Eigen::MatrixXd c(2, f.size());
  c.row(0) = f.coefs().row(0);
  c.row(1).setOnes();  // 1 in F's basis (partition of unity)
  std::vector<int> factor_rows(D + 1, 0);
  factor_rows[D] = 1;
  BSpline h = product_rows(BSpline(f.degree(), f.knots(), std::move(c)), factor_rows,
                           B.homogeneous(), iota_rows(D + 1));
  if (removal_tol > 0.0) h = remove_removable_knots(h, homogeneous_tolerance(h, removal_tol));
  return NurbsCurve<D>(std::move(h));
}

template NurbsCurve<2> product(const BSplineFunction&, const NurbsCurve<2>&, double);
template NurbsCurve<3> product(const BSplineFunction&, const NurbsCurve<3>&, double);

// Bae 2002, eq. (B.2).
NurbsSurface product(const BSplineSurface& F, const NurbsSurface& B, double removal_tol) {
  check_scalar(F, "spherical product");
  check_removal_tol(removal_tol, "spherical product");
  return finish(product_rows(with_one(F), {0, 0, 0, 1}, B.homogeneous(), iota_rows(4)),
                removal_tol);
}

// Bae 2002, eqs. (B.3) and (B.8).
NurbsSurface cylindrical_product(const BSplineSurface& F, const NurbsSurface& B,
                                 double removal_tol) {
  check_scalar(F, "cylindrical product");
  check_removal_tol(removal_tol, "cylindrical product");
  const BSplineSurface& b = B.homogeneous();
  const int nu = b.size_u(), nv = b.size_v();
  const double eps = 1e-12 * b.coefs().cwiseAbs().maxCoeff();
  // The base must be a cylinder along u: X^w, Y^w, W constant in u and Z^w = z(u)·W(v).
  Eigen::RowVectorXd z(nu);
  for (int i = 0; i < nu; ++i) {
    z(i) = b.coef(i, 0)(2) / b.coef(i, 0)(3);
    for (int j = 0; j < nv; ++j) {
      for (int row : {0, 1, 3})
        if (std::abs(b.coef(i, j)(row) - b.coef(0, j)(row)) > eps)
          throw InputError("cylindrical product: base control point (" + std::to_string(i) + ", " +
                           std::to_string(j) + ") leaves the circle of row 0 (X^w, Y^w, W must " +
                           "not vary along u)");
      if (std::abs(b.coef(i, j)(2) - z(i) * b.coef(i, j)(3)) > eps)
        throw InputError("cylindrical product: base control point (" + std::to_string(i) + ", " +
                         std::to_string(j) + ") has a height differing from z(u) of its row " +
                         "(Z^w must be z(u)·W(v))");
    }
  }
  const double u0 = b.front_u(), u1 = b.back_u(), v0 = b.front_v(), v1 = b.back_v();
  Eigen::MatrixXd circle(3, nv);  // (X^w, Y^w, W) of row 0, degree 0 along u
  for (int j = 0; j < nv; ++j) circle.col(j) << b.coef(0, j)(0), b.coef(0, j)(1), b.coef(0, j)(3);
  const BSplineSurface base(0, b.degree_v(), {u0, u1}, b.knots_v(), std::move(circle));
  const BSplineSurface height(b.degree_u(), 0, b.knots_u(), {v0, v1}, z);
  const BSplineSurface one(0, 0, {u0, u1}, {v0, v1}, Eigen::MatrixXd::Ones(1, 1));
  // Rows (F·X^w, F·Y^w, z·W, 1·W).
  return finish(product_rows(common_basis({F, height, one}), {0, 0, 1, 2}, base, {0, 1, 2, 2}),
                removal_tol);
}

}  // namespace polarform
