// NurbsSurface: a rational tensor-product B-spline surface in 3D, stored homogeneously as the
// BSplineSurface of (w·P, w). Weights are validated positive. NURBS Book A4.3 / A4.4.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

class NurbsSurface {
 public:
  using Point = Eigen::Vector3d;
  // Control points indexed (i, j) -> points[i * nv + j], i along u.
  using Points = std::vector<Point>;

  NurbsSurface() = default;
  // Non-rational when weights is empty.
  NurbsSurface(int degree_u, int degree_v, Knots knots_u, Knots knots_v, const Points& points,
               const std::vector<double>& weights = {});
  // From the homogeneous B-spline surface (dim 4, last row the weights).
  explicit NurbsSurface(BSplineSurface homogeneous);

  int degree_u() const { return h_.degree_u(); }
  int degree_v() const { return h_.degree_v(); }
  int size_u() const { return h_.size_u(); }
  int size_v() const { return h_.size_v(); }
  const Knots& knots_u() const { return h_.knots_u(); }
  const Knots& knots_v() const { return h_.knots_v(); }
  const BSplineSurface& homogeneous() const { return h_; }
  double front_u() const { return h_.front_u(); }
  double back_u() const { return h_.back_u(); }
  double front_v() const { return h_.front_v(); }
  double back_v() const { return h_.back_v(); }

  double weight(int i, int j) const { return h_.coef(i, j)(3); }
  Point control_point(int i, int j) const { return h_.coef(i, j).head<3>() / weight(i, j); }
  bool is_rational() const;

  // NURBS Book A4.3.
  Point point(double u, double v) const;
  Point operator()(double u, double v) const { return point(u, v); }
  // S_{k,l} = d^{k+l}S/du^k dv^l for k + l <= d, at index k * (d + 1) + l; NURBS Book A4.4.
  Points derivatives(double u, double v, int d) const;
  // Unit normal S_u x S_v (zero vector where the surface degenerates).
  Point normal(double u, double v) const;

 private:
  void check_weights() const;
  BSplineSurface h_;
};

}  // namespace polarform
