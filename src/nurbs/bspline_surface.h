// BSplineSurface: a non-rational tensor-product B-spline with vector-valued coefficients, the
// surface counterpart of BSpline (a NURBS surface stores its homogeneous net in one). The net is a
// dim x (nu·nv) matrix whose column i·nv + j holds control value (i, j), i along u, j along v.
// along_u()/along_v() view the surface as a curve in one direction with the other direction folded
// into the coefficients, so every curve algorithm works on surfaces direction by direction.
#pragma once

#include <Eigen/Core>

#include "src/nurbs/bspline.h"

namespace polarform {

class BSplineSurface {
 public:
  BSplineSurface() = default;
  BSplineSurface(int degree_u, int degree_v, Knots knots_u, Knots knots_v, Eigen::MatrixXd coefs);

  int degree_u() const { return pu_; }
  int degree_v() const { return pv_; }
  int size_u() const { return static_cast<int>(U_.size()) - pu_ - 1; }
  int size_v() const { return static_cast<int>(V_.size()) - pv_ - 1; }
  int dim() const { return static_cast<int>(coefs_.rows()); }
  const Knots& knots_u() const { return U_; }
  const Knots& knots_v() const { return V_; }
  const Eigen::MatrixXd& coefs() const { return coefs_; }
  auto coef(int i, int j) const { return coefs_.col(i * size_v() + j); }
  double front_u() const { return U_[pu_]; }
  double back_u() const { return U_[size_u()]; }
  double front_v() const { return V_[pv_]; }
  double back_v() const { return V_[size_v()]; }

  // Point at (u, v) into out[0..dim-1]; NURBS Book A3.5.
  void point(double u, double v, double* out) const;
  Eigen::VectorXd point(double u, double v) const;
  // Mixed partials d^{k+l}/du^k dv^l for k + l <= d as the column k·(d+1) + l of a
  // dim x (d+1)^2 matrix (entries with k + l > d are zero); NURBS Book A3.6.
  Eigen::MatrixXd derivatives(double u, double v, int d) const;

  // The surface as a u-direction curve with (dim·nv)-dimensional coefficients, and back.
  BSpline along_u() const;
  static BSplineSurface from_along_u(const BSpline& curve, int degree_v, Knots knots_v, int dim);
  // The surface as a v-direction curve with (dim·nu)-dimensional coefficients, and back.
  BSpline along_v() const;
  static BSplineSurface from_along_v(const BSpline& curve, int degree_u, Knots knots_u, int dim);

  bool operator==(const BSplineSurface& other) const = default;

 private:
  int pu_ = 0, pv_ = 0;
  Knots U_, V_;
  Eigen::MatrixXd coefs_;
};

}  // namespace polarform
