#include "designers/convert/spline_space.h"

#include "src/error.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/periodic.h"

namespace polarform {

SplineSpace::SplineSpace(int degree, bool periodic, std::vector<double> breaks)
    : degree_(degree), periodic_(periodic), breaks_(std::move(breaks)) {
  const int k = spans();
  if (k < 1 || (periodic_ && k < degree_ + 1))
    throw InputError("spline space: too few spans for degree " + std::to_string(degree_));
  if (periodic_) {
    knots_ = periodic_knots(degree_, breaks_);
    size_ = k;
  } else {
    knots_ = clamped_knots(degree_, breaks_.front(), breaks_.back(),
                           std::vector<double>(breaks_.begin() + 1, breaks_.end() - 1));
    size_ = k + degree_;
  }
  n_ = static_cast<int>(knots_.size()) - degree_ - 1;
}

int SplineSpace::basis(double t, double* N) const {
  const int span = find_span(degree_, knots_, n_, t);
  basis_funs(span, t, degree_, knots_, N);
  return span - degree_;
}

Eigen::Vector2d SplineSpace::point(const Eigen::MatrixXd& coefs, double t) const {
  double N[kMaxDegree + 1];
  const int first = basis(t, N);
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  for (int j = 0; j <= degree_; ++j) p += N[j] * coefs.col((first + j) % size_);
  return p;
}

NurbsCurve2d SplineSpace::curve(const Eigen::MatrixXd& coefs) const {
  const BSpline plain =
      periodic_ ? clip(periodic_bspline(degree_, breaks_, coefs), breaks_.front(), breaks_.back())
                : BSpline(degree_, knots_, coefs);
  Eigen::MatrixXd h(3, plain.size());
  h.topRows(2) = plain.coefs();
  h.row(2).setOnes();
  return NurbsCurve2d(BSpline(degree_, plain.knots(), std::move(h)));
}

}  // namespace polarform
