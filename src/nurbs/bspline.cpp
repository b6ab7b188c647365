#include "src/nurbs/bspline.h"

#include <string>

#include "src/error.h"
#include "src/nurbs/basis.h"

namespace polarform {

BSpline::BSpline(int degree, Knots knots, Eigen::MatrixXd coefs)
    : degree_(degree), knots_(std::move(knots)), coefs_(std::move(coefs)) {
  validate_knots(degree_, knots_, size(), "B-spline");
  if (dim() < 1) throw InputError("B-spline: coefficients have no rows");
  if (!coefs_.allFinite()) throw InputError("B-spline: a coefficient is not finite");
}

void BSpline::point(double u, double* out) const {
  const int p = degree_, n = size(), d = dim();
  const int span = find_span(p, knots_, n, u);
  double N[kMaxDegree + 1];
  basis_funs(span, u, p, knots_, N);
  for (int k = 0; k < d; ++k) out[k] = 0.0;
  for (int j = 0; j <= p; ++j) {
    const double* c = coefs_.col(span - p + j).data();
    for (int k = 0; k < d; ++k) out[k] += N[j] * c[k];
  }
}

Eigen::VectorXd BSpline::point(double u) const {
  Eigen::VectorXd out(dim());
  point(u, out.data());
  return out;
}

Eigen::MatrixXd BSpline::derivatives(double u, int d) const {
  const int p = degree_, n = size();
  const int span = find_span(p, knots_, n, u);
  const Eigen::MatrixXd ders = ders_basis_funs(span, u, p, d, knots_);
  return coefs_.middleCols(span - p, p + 1) * ders.transpose();
}

BSpline BSpline::derivative() const {
  const int p = degree_, n = size();
  if (p == 0) return BSpline(0, knots_, Eigen::MatrixXd::Zero(dim(), n));
  Eigen::MatrixXd q(dim(), n - 1);
  for (int i = 0; i < n - 1; ++i) {
    const double du = knots_[i + p + 1] - knots_[i + 1];
    q.col(i) = du > 0 ? Eigen::VectorXd(p * (coefs_.col(i + 1) - coefs_.col(i)) / du)
                      : Eigen::VectorXd::Zero(dim());
  }
  return BSpline(p - 1, Knots(knots_.begin() + 1, knots_.end() - 1), std::move(q));
}

BSplineFunction::BSplineFunction(int degree, Knots knots, const Eigen::VectorXd& values)
    : spline_(degree, std::move(knots), values.transpose()) {}

BSplineFunction::BSplineFunction(BSpline spline) : spline_(std::move(spline)) {
  if (spline_.dim() != 1)
    throw InputError("B-spline function: expected scalar coefficients, got dimension " +
                     std::to_string(spline_.dim()));
}

double BSplineFunction::operator()(double u) const {
  double value;
  spline_.point(u, &value);
  return value;
}

Eigen::VectorXd BSplineFunction::derivatives(double u, int d) const {
  return spline_.derivatives(u, d).row(0).transpose();
}

}  // namespace polarform
