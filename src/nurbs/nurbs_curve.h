// NurbsCurve<Dim>: a rational B-spline curve in 2D or 3D, stored homogeneously as the BSpline of
// (w·P, w). Weights are validated positive. Evaluation and derivatives: NURBS Book A4.1 / A4.2.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/bspline.h"

namespace polarform {

template <int Dim>
class NurbsCurve {
 public:
  static_assert(Dim == 2 || Dim == 3, "NurbsCurve is 2D or 3D");
  using Point = Eigen::Matrix<double, Dim, 1>;
  using Points = std::vector<Point>;  // C++17 aligned new: no aligned_allocator needed

  NurbsCurve() = default;
  // Non-rational when weights is empty.
  NurbsCurve(int degree, Knots knots, const Points& points, const std::vector<double>& weights = {})
      : homogeneous_(degree, std::move(knots), homogenize(points, weights)) {
    check_weights();
  }
  // From the homogeneous B-spline (dim Dim+1, last row the weights).
  explicit NurbsCurve(BSpline homogeneous) : homogeneous_(std::move(homogeneous)) {
    if (homogeneous_.dim() != Dim + 1)
      throw InputError("NURBS curve: homogeneous dimension " + std::to_string(homogeneous_.dim()) +
                       ", expected " + std::to_string(Dim + 1));
    check_weights();
  }

  int degree() const { return homogeneous_.degree(); }
  int size() const { return homogeneous_.size(); }
  const Knots& knots() const { return homogeneous_.knots(); }
  const BSpline& homogeneous() const { return homogeneous_; }
  double front() const { return homogeneous_.front(); }
  double back() const { return homogeneous_.back(); }

  double weight(int i) const { return homogeneous_.coefs()(Dim, i); }
  Point control_point(int i) const {
    return homogeneous_.coefs().col(i).template head<Dim>() / weight(i);
  }
  Points control_points() const {
    Points out(size());
    for (int i = 0; i < size(); ++i) out[i] = control_point(i);
    return out;
  }
  std::vector<double> weights() const {
    const auto w = homogeneous_.coefs().row(Dim);
    return std::vector<double>(w.begin(), w.end());
  }
  // True when some weight differs from the first (a common factor is not rational).
  bool is_rational() const {
    const auto w = homogeneous_.coefs().row(Dim);
    return (w.array() != w(0)).any();
  }

  // NURBS Book A4.1.
  Point point(double u) const {
    double h[Dim + 1];
    homogeneous_.point(u, h);
    Point out;
    for (int k = 0; k < Dim; ++k) out[k] = h[k] / h[Dim];
    return out;
  }
  Point operator()(double u) const { return point(u); }

  // C(u), C'(u), ..., C^(d)(u); NURBS Book A4.2.
  Points derivatives(double u, int d) const {
    const Eigen::MatrixXd Aw = homogeneous_.derivatives(u, d);
    Points ck(d + 1);
    for (int k = 0; k <= d; ++k) {
      Point v = Aw.col(k).template head<Dim>();
      double binom = 1.0;  // C(k, i)
      for (int i = 1; i <= k; ++i) {
        binom = binom * (k - i + 1) / i;
        v -= binom * Aw(Dim, i) * ck[k - i];
      }
      ck[k] = v / Aw(Dim, 0);
    }
    return ck;
  }

 private:
  static Eigen::MatrixXd homogenize(const Points& points, const std::vector<double>& weights) {
    if (!weights.empty() && weights.size() != points.size())
      throw InputError("NURBS curve: " + std::to_string(weights.size()) + " weights for " +
                       std::to_string(points.size()) + " control points");
    Eigen::MatrixXd h(Dim + 1, points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double w = weights.empty() ? 1.0 : weights[i];
      h.col(i).template head<Dim>() = w * points[i];
      h(Dim, i) = w;
    }
    return h;
  }
  void check_weights() const {
    for (int i = 0; i < size(); ++i)
      if (!(weight(i) > 0.0))
        throw InputError("NURBS curve: weight " + std::to_string(i) + " is " +
                         std::to_string(weight(i)) + ", weights must be > 0");
  }

  BSpline homogeneous_;
};

using NurbsCurve2d = NurbsCurve<2>;
using NurbsCurve3d = NurbsCurve<3>;

}  // namespace polarform
