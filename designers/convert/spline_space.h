// The spline space of a degree-limited profile: a planar B-spline of degree p on the breaks
// b_0 = a < ... < b_k = b (interior knots simple, or of a given multiplicity m: C^{p-m} there),
// clamped, periodic (control values wrap, C^{p-1} across b / a, Bae 2002, eq. 3.9-3.10, or
// C^{p-m} with a seam knot of multiplicity m), or mirrored: continued past b as its own mirror
// image in the line through the origin at polar angle b, its control values tied in mirror pairs
// (a vessel head's meridian, mirrored in its axis). Evaluates from its distinct control values and
// turns them into the clamped curve that is exported.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/knots.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

enum class Ends {
  clamped,   // the curve ends at a and b
  periodic,  // at least p + 1 spans
  // To 2b − a through the mirror images b_i' = 2b − b_i of the breaks: the control values
  // P_{N−1−i} = S·P_i (S the reflection in the line; a middle one, N odd, on the line), with a
  // simple knot at b, or (mirrored_smooth) none, the span that ends at b running on across it.
  mirrored,
  mirrored_smooth,
};

// The knots of a space that are not simple, each of multiplicity 1..p: a periodic space's seam
// (C^{p-m} across b / a) and interior breaks (sorted by the break, which must be one of the
// space's; a mirrored space's images of them alike).
struct Multiplicities {
  int seam = 1;
  std::vector<std::pair<double, int>> interior;
};

class SplineSpace {
 public:
  // breaks: increasing, at least 2 (periodic: enough for p + 1 distinct control values).
  SplineSpace(int degree, Ends ends, std::vector<double> breaks, Multiplicities multiple = {});

  int degree() const { return degree_; }
  Ends ends() const { return ends_; }
  const Multiplicities& multiplicities() const { return multiple_; }
  bool periodic() const { return ends_ == Ends::periodic; }
  bool mirrored() const { return ends_ == Ends::mirrored || ends_ == Ends::mirrored_smooth; }
  // Of [a, b], where the fits sample and measure (a mirrored curve's other half is the image).
  int spans() const { return static_cast<int>(breaks_.size()) - 1; }
  int size() const { return size_; }  // distinct control values
  const std::vector<double>& breaks() const { return breaks_; }

  // The p+1 basis values at t into N[0..p]; returns the index k of the first one's control value
  // among the curve's (the others follow): value(k + j) is its distinct control value, reflected
  // by reflection() when reflected(k + j).
  int basis(double t, double* N) const;
  // basis() at `count` parameters t[0..count) of the span [b_j, b_{j+1}], into N[i·(p+1) + j].
  int basis_on_span(int j, const double* t, int count, double* N) const;
  int value(int k) const { return periodic() ? k % size_ : reflected(k) ? n_ - 1 - k : k; }
  bool reflected(int k) const { return mirrored() && 2 * k > n_ - 1; }
  const Eigen::Matrix2d& reflection() const { return reflection_; }
  // A mirrored space with an odd number of control values: the middle (distinct) one, which lies
  // on the mirror line.
  bool middle_on_mirror_line() const { return mirrored() && n_ % 2 == 1; }

  // The point at t of the distinct control values `coefs` (2 x size).
  Eigen::Vector2d point(const Eigen::MatrixXd& coefs, double t) const;
  // The point of the basis values N[0..p] returned by basis() or basis_on_span() as `first`.
  Eigen::Vector2d point(const Eigen::MatrixXd& coefs, int first, const double* N) const;
  // The clamped curve of the distinct control values (2 x size); a mirrored one over [a, 2b − a].
  NurbsCurve2d curve(const Eigen::MatrixXd& coefs) const;

 private:
  // The curve's N control values from the distinct ones (a periodic space's before clipping).
  Eigen::MatrixXd unfolded(const Eigen::MatrixXd& coefs) const;

  int degree_;
  Ends ends_;
  Multiplicities multiple_;
  std::vector<double> breaks_;
  Knots knots_;
  int size_, n_;  // distinct control values; the curve's (periodic: of its unclipped knots)
  Eigen::Matrix2d reflection_ = Eigen::Matrix2d::Identity();
};

}  // namespace polarform
