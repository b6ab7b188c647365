#include "src/nurbs/nurbs_surface.h"

#include <Eigen/Geometry>

#include "src/nurbs/binomial.h"

namespace polarform {

namespace {

Eigen::MatrixXd homogenize(const NurbsSurface::Points& points, const std::vector<double>& weights) {
  if (!weights.empty() && weights.size() != points.size())
    throw InputError("NURBS surface: " + std::to_string(weights.size()) + " weights for " +
                     std::to_string(points.size()) + " control points");
  Eigen::MatrixXd h(4, points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    h.col(i).head<3>() = w * points[i];
    h(3, i) = w;
  }
  return h;
}

}  // namespace

NurbsSurface::NurbsSurface(int degree_u, int degree_v, Knots knots_u, Knots knots_v,
                           const Points& points, const std::vector<double>& weights)
    : h_(degree_u, degree_v, std::move(knots_u), std::move(knots_v), homogenize(points, weights)) {
  check_weights();
}

NurbsSurface::NurbsSurface(BSplineSurface homogeneous) : h_(std::move(homogeneous)) {
  if (h_.dim() != 4)
    throw InputError("NURBS surface: homogeneous dimension " + std::to_string(h_.dim()) +
                     ", expected 4");
  check_weights();
}

void NurbsSurface::check_weights() const {
  for (int i = 0; i < size_u(); ++i)
    for (int j = 0; j < size_v(); ++j)
      if (!(weight(i, j) > 0.0))
        throw InputError("NURBS surface: weight (" + std::to_string(i) + ", " + std::to_string(j) +
                         ") is " + std::to_string(weight(i, j)) + ", weights must be > 0");
}

bool NurbsSurface::is_rational() const {
  const auto w = h_.coefs().row(3);
  return (w.array() != w(0)).any();
}

NurbsSurface::Point NurbsSurface::point(double u, double v) const {
  double h[4];
  h_.point(u, v, h);
  return Point(h[0], h[1], h[2]) / h[3];
}

NurbsSurface::Points NurbsSurface::derivatives(double u, double v, int d) const {
  const Eigen::MatrixXd Sw = h_.derivatives(u, v, d);
  const int w = d + 1;
  auto A = [&](int k, int l) -> Point { return Sw.col(k * w + l).head<3>(); };
  auto W = [&](int k, int l) { return Sw(3, k * w + l); };
  Points skl(w * w, Point::Zero());
  for (int k = 0; k <= d; ++k) {
    for (int l = 0; l <= d - k; ++l) {
      Point v2 = A(k, l);
      for (int j = 1; j <= l; ++j) v2 -= binomial(l, j) * W(0, j) * skl[k * w + l - j];
      for (int i = 1; i <= k; ++i) {
        v2 -= binomial(k, i) * W(i, 0) * skl[(k - i) * w + l];
        Point v3 = Point::Zero();
        for (int j = 1; j <= l; ++j) v3 += binomial(l, j) * W(i, j) * skl[(k - i) * w + l - j];
        v2 -= binomial(k, i) * v3;
      }
      skl[k * w + l] = v2 / W(0, 0);
    }
  }
  return skl;
}

NurbsSurface::Point NurbsSurface::normal(double u, double v) const {
  const Points d = derivatives(u, v, 1);
  const Point n = d[1 * 2 + 0].cross(d[0 * 2 + 1]);
  const double len = n.norm();
  return len > 0 ? Point(n / len) : Point::Zero();
}

}  // namespace polarform
