// The spline space of a degree-limited profile: a planar B-spline of degree p on the breaks
// b_0 = a < ... < b_k = b (simple interior knots), periodic (control values wrap, C^{p-1} across
// b / a; Bae 2002, eq. 3.9-3.10) or clamped. Evaluates from its distinct control values and turns
// them into the clamped curve that is exported.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/knots.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

class SplineSpace {
 public:
  // breaks: increasing, at least 2 (periodic: at least degree + 1 spans).
  SplineSpace(int degree, bool periodic, std::vector<double> breaks);

  int degree() const { return degree_; }
  bool periodic() const { return periodic_; }
  int spans() const { return static_cast<int>(breaks_.size()) - 1; }
  int size() const { return size_; }  // distinct control values
  const std::vector<double>& breaks() const { return breaks_; }

  // The p+1 basis values at t into N[0..p]; returns the index of the first one's control value
  // (the others follow, modulo size() when periodic).
  int basis(double t, double* N) const;
  // The point at t of the distinct control values `coefs` (2 x size).
  Eigen::Vector2d point(const Eigen::MatrixXd& coefs, double t) const;
  // The clamped curve of the distinct control values (2 x size).
  NurbsCurve2d curve(const Eigen::MatrixXd& coefs) const;

 private:
  int degree_;
  bool periodic_;
  std::vector<double> breaks_;
  Knots knots_;
  int size_, n_;
};

}  // namespace polarform
