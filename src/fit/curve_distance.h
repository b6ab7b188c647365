// True distances of many points to one NURBS curve, fast: the curve is sampled densely (per knot
// span), the nearest sample is found in a grid index (spec B3) and Newton on C'(u)·(C(u) − P) = 0
// (NURBS Book §6.1, eq. (6.3)) polishes it inside its smooth piece (between C0 knots). The result
// is never worse than the nearest sample, so every distance is an upper bound of the true one and
// equal to it wherever the sampling resolves the curve (exact inversion: point_inversion.h,
// slower).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "src/fit/grid_index.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

template <int Dim>
class CurveDistance {
 public:
  using Point = Eigen::Matrix<double, Dim, 1>;

  // samples_per_span samples in every non-empty knot span (ends included). `closed` wraps Newton
  // across the domain ends (a periodic curve).
  explicit CurveDistance(const NurbsCurve<Dim>& curve, bool closed = false,
                         int samples_per_span = 24);
  // The grid index refers to the samples: neither copied nor moved.
  CurveDistance(const CurveDistance&) = delete;
  CurveDistance& operator=(const CurveDistance&) = delete;

  struct Foot {
    double u = 0.0;
    double distance = 0.0;
  };
  // The closest point's parameter and the distance; thread-safe.
  Foot project(const Point& p) const;

 private:
  double newton(const Point& p, double u, double lo, double hi) const;

  const NurbsCurve<Dim>* curve_;
  std::vector<double> kinks_;  // front, the knots of multiplicity >= degree, back
  bool closed_;
  Eigen::VectorXd u_;
  Eigen::Matrix<double, Dim, Eigen::Dynamic> samples_;
  std::unique_ptr<GridIndex<Dim>> grid_;
};

}  // namespace polarform
