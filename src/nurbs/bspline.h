// BSpline: a non-rational B-spline with vector-valued coefficients (one column per control value).
// It is the kernel's workhorse: a scalar B-spline function has dim 1, a NURBS curve is stored as the
// BSpline of its homogeneous control points (w·x, w·y, [w·z,] w), and every knot algorithm
// (insertion, refinement, removal, Bezier decomposition, degree elevation, products) is written once
// for it.
#pragma once

#include <Eigen/Core>

#include "src/nurbs/knots.h"

namespace polarform {

class BSpline {
 public:
  BSpline() = default;
  // Validates degree, knots (see validate_knots) and finiteness of the coefficients.
  BSpline(int degree, Knots knots, Eigen::MatrixXd coefs);

  int degree() const { return degree_; }
  int dim() const { return static_cast<int>(coefs_.rows()); }
  int size() const { return static_cast<int>(coefs_.cols()); }
  const Knots& knots() const { return knots_; }
  const Eigen::MatrixXd& coefs() const { return coefs_; }
  // Parameter domain [u_p, u_n].
  double front() const { return knots_[degree_]; }
  double back() const { return knots_[size()]; }

  // Point at u, written to out[0..dim-1] without allocating; NURBS Book A3.1.
  void point(double u, double* out) const;
  Eigen::VectorXd point(double u) const;
  // Derivatives 0..d at u as the columns of a dim x (d+1) matrix; NURBS Book A3.2.
  Eigen::MatrixXd derivatives(double u, int d) const;
  // The derivative as a B-spline of degree p-1 (degree 0 stays a zero function); NURBS Book A3.3.
  BSpline derivative() const;

  bool operator==(const BSpline& other) const = default;

 private:
  int degree_ = 0;
  Knots knots_;
  Eigen::MatrixXd coefs_;
};

// A scalar B-spline function F(u) = sum N_{i,p}(u) f_i.
class BSplineFunction {
 public:
  BSplineFunction() = default;
  BSplineFunction(int degree, Knots knots, const Eigen::VectorXd& values);
  explicit BSplineFunction(BSpline spline);  // spline.dim() must be 1

  int degree() const { return spline_.degree(); }
  int size() const { return spline_.size(); }
  const Knots& knots() const { return spline_.knots(); }
  Eigen::VectorXd values() const { return spline_.coefs().row(0).transpose(); }
  double front() const { return spline_.front(); }
  double back() const { return spline_.back(); }
  const BSpline& spline() const { return spline_; }

  double operator()(double u) const;
  // F, F', ..., F^(d) at u.
  Eigen::VectorXd derivatives(double u, int d) const;
  BSplineFunction derivative() const { return BSplineFunction(spline_.derivative()); }

 private:
  BSpline spline_;
};

}  // namespace polarform
