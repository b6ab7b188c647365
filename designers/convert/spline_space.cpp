#include "designers/convert/spline_space.h"

#include <cmath>

#include "src/error.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/periodic.h"

namespace polarform {

SplineSpace::SplineSpace(int degree, Ends ends, std::vector<double> breaks, Multiplicities multiple)
    : degree_(degree), ends_(ends), multiple_(std::move(multiple)), breaks_(std::move(breaks)) {
  const int k = spans();
  const auto bad = [&](int m) { return m < 1 || m > std::max(1, degree_); };
  if (bad(multiple_.seam) || (multiple_.seam > 1 && !periodic()))
    throw InputError("spline space: seam multiplicity " + std::to_string(multiple_.seam) +
                     " for degree " + std::to_string(degree_));
  if (k < 1) throw InputError("spline space: no span");
  const double a = breaks_.front(), b = breaks_.back();
  // The interior breaks, each as often as its multiplicity.
  std::vector<double> interior;
  auto m = multiple_.interior.begin();
  for (std::size_t i = 1; i + 1 < breaks_.size(); ++i) {
    while (m != multiple_.interior.end() && m->first < breaks_[i]) ++m;
    const int times = m != multiple_.interior.end() && m->first == breaks_[i] ? m->second : 1;
    if (bad(times))
      throw InputError("spline space: knot multiplicity " + std::to_string(times) + " for degree " +
                       std::to_string(degree_));
    interior.insert(interior.end(), static_cast<std::size_t>(times), breaks_[i]);
  }
  if (periodic()) {
    // One period's knots (a as often as the seam's multiplicity, then the interior ones), K
    // control values, wrapping.
    std::vector<double> T(static_cast<std::size_t>(multiple_.seam), a);
    T.insert(T.end(), interior.begin(), interior.end());
    if (static_cast<int>(T.size()) < degree_ + 1)
      throw InputError("spline space: too few spans for degree " + std::to_string(degree_));
    knots_ = periodic_knots(degree_, T, b);
    size_ = static_cast<int>(T.size());
  } else if (!mirrored()) {
    knots_ = clamped_knots(degree_, a, b, interior);
    size_ = static_cast<int>(interior.size()) + 1 + degree_;
  } else {
    const std::size_t half = interior.size();
    if (ends_ == Ends::mirrored) interior.push_back(b);
    for (std::size_t i = half; i-- > 0;) interior.push_back(2 * b - interior[i]);
    knots_ = clamped_knots(degree_, a, 2 * b - a, interior);
    const int n = static_cast<int>(interior.size()) + 1 + degree_;
    size_ = (n + 1) / 2;
    // The reflection in the line at angle b: (x, y) → (x cos 2b + y sin 2b, x sin 2b − y cos 2b).
    reflection_ << std::cos(2 * b), std::sin(2 * b), std::sin(2 * b), -std::cos(2 * b);
  }
  n_ = static_cast<int>(knots_.size()) - degree_ - 1;
}

int SplineSpace::basis(double t, double* N) const {
  const int span = find_span(degree_, knots_, n_, t);
  basis_funs(span, t, degree_, knots_, N);
  return span - degree_;
}

int SplineSpace::basis_on_span(int j, const double* t, int count, double* N) const {
  const int span = find_span(degree_, knots_, n_, 0.5 * (breaks_[j] + breaks_[j + 1]));
  basis_funs_on_span(span, t, count, degree_, knots_, N);
  return span - degree_;
}

Eigen::Vector2d SplineSpace::point(const Eigen::MatrixXd& coefs, double t) const {
  double N[kMaxDegree + 1];
  const int first = basis(t, N);
  return point(coefs, first, N);
}

Eigen::Vector2d SplineSpace::point(const Eigen::MatrixXd& coefs, int first, const double* N) const {
  Eigen::Vector2d p = Eigen::Vector2d::Zero(), q = Eigen::Vector2d::Zero();
  for (int j = 0; j <= degree_; ++j)
    (reflected(first + j) ? q : p) += N[j] * coefs.col(value(first + j));
  return p + reflection_ * q;
}

NurbsCurve2d SplineSpace::curve(const Eigen::MatrixXd& coefs) const {
  const BSpline all(degree_, knots_, ends_ == Ends::clamped ? coefs : unfolded(coefs));
  const BSpline plain = periodic() ? clip(all, breaks_.front(), breaks_.back()) : all;
  Eigen::MatrixXd h(3, plain.size());
  h.topRows(2) = plain.coefs();
  h.row(2).setOnes();
  return NurbsCurve2d(BSpline(degree_, plain.knots(), std::move(h)));
}

Eigen::MatrixXd SplineSpace::unfolded(const Eigen::MatrixXd& coefs) const {
  Eigen::MatrixXd out(2, n_);
  for (int k = 0; k < n_; ++k)
    out.col(k) = reflected(k) ? Eigen::Vector2d(reflection_ * coefs.col(value(k)))
                              : Eigen::Vector2d(coefs.col(value(k)));
  return out;
}

}  // namespace polarform
