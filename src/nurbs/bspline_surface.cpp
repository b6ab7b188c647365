#include "src/nurbs/bspline_surface.h"

#include <string>

#include "src/error.h"
#include "src/nurbs/basis.h"

namespace polarform {

BSplineSurface::BSplineSurface(int degree_u, int degree_v, Knots knots_u, Knots knots_v,
                               Eigen::MatrixXd coefs)
    : pu_(degree_u), pv_(degree_v), U_(std::move(knots_u)), V_(std::move(knots_v)),
      coefs_(std::move(coefs)) {
  validate_knots(pu_, U_, size_u(), "B-spline surface (u)");
  validate_knots(pv_, V_, size_v(), "B-spline surface (v)");
  if (coefs_.cols() != static_cast<Eigen::Index>(size_u()) * size_v())
    throw InputError("B-spline surface: " + std::to_string(coefs_.cols()) +
                     " control values, expected " + std::to_string(size_u()) + " x " +
                     std::to_string(size_v()));
  if (dim() < 1) throw InputError("B-spline surface: coefficients have no rows");
  if (!coefs_.allFinite()) throw InputError("B-spline surface: a coefficient is not finite");
}

void BSplineSurface::point(double u, double v, double* out) const {
  const int nu = size_u(), nv = size_v(), d = dim();
  const int su = find_span(pu_, U_, nu, u), sv = find_span(pv_, V_, nv, v);
  double Nu[kMaxDegree + 1], Nv[kMaxDegree + 1];
  basis_funs(su, u, pu_, U_, Nu);
  basis_funs(sv, v, pv_, V_, Nv);
  for (int k = 0; k < d; ++k) out[k] = 0.0;
  for (int a = 0; a <= pu_; ++a) {
    const double* row = coefs_.col((su - pu_ + a) * nv + sv - pv_).data();
    for (int b = 0; b <= pv_; ++b) {
      const double w = Nu[a] * Nv[b];
      for (int k = 0; k < d; ++k) out[k] += w * row[b * d + k];
    }
  }
}

Eigen::VectorXd BSplineSurface::point(double u, double v) const {
  Eigen::VectorXd out(dim());
  point(u, v, out.data());
  return out;
}

Eigen::MatrixXd BSplineSurface::derivatives(double u, double v, int d) const {
  const int nu = size_u(), nv = size_v();
  const int su = find_span(pu_, U_, nu, u), sv = find_span(pv_, V_, nv, v);
  const Eigen::MatrixXd Du = ders_basis_funs(su, u, pu_, d, U_);
  const Eigen::MatrixXd Dv = ders_basis_funs(sv, v, pv_, d, V_);
  Eigen::MatrixXd skl = Eigen::MatrixXd::Zero(dim(), (d + 1) * (d + 1));
  for (int k = 0; k <= d; ++k) {
    for (int l = 0; l <= d - k; ++l) {
      for (int a = 0; a <= pu_; ++a)
        for (int b = 0; b <= pv_; ++b)
          skl.col(k * (d + 1) + l) += Du(k, a) * Dv(l, b) * coef(su - pu_ + a, sv - pv_ + b);
    }
  }
  return skl;
}

BSpline BSplineSurface::along_u() const {
  // Column i of the (dim·nv) x nu view holds the whole v-row i: same memory, reshaped.
  return BSpline(pu_, U_, coefs_.reshaped(dim() * size_v(), size_u()));
}

BSplineSurface BSplineSurface::from_along_u(const BSpline& curve, int degree_v, Knots knots_v,
                                            int dim) {
  const int nv = static_cast<int>(knots_v.size()) - degree_v - 1;
  if (curve.dim() != dim * nv)
    throw InputError("B-spline surface: u-curve dimension does not match dim x nv");
  return BSplineSurface(curve.degree(), degree_v, curve.knots(), std::move(knots_v),
                        curve.coefs().reshaped(dim, curve.size() * nv));
}

BSpline BSplineSurface::along_v() const {
  const int nu = size_u(), nv = size_v(), d = dim();
  Eigen::MatrixXd c(d * nu, nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) c.block(i * d, j, d, 1) = coef(i, j);
  return BSpline(pv_, V_, std::move(c));
}

BSplineSurface BSplineSurface::from_along_v(const BSpline& curve, int degree_u, Knots knots_u,
                                            int dim) {
  const int nu = static_cast<int>(knots_u.size()) - degree_u - 1, nv = curve.size();
  if (curve.dim() != dim * nu)
    throw InputError("B-spline surface: v-curve dimension does not match dim x nu");
  Eigen::MatrixXd c(dim, nu * nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) c.col(i * nv + j) = curve.coefs().block(i * dim, j, dim, 1);
  return BSplineSurface(degree_u, curve.degree(), std::move(knots_u), curve.knots(), std::move(c));
}

}  // namespace polarform
