// A dense table of a polar function for the many evaluations of an iterative fit: R, R' and R''
// at nodes spaced at most 2π/4096 apart (R's breakpoints among them, each side's derivatives
// taken from inside the interval), evaluated between nodes by quintic Hermite interpolation, so
// that no interval straddles a breakpoint. Accurate to far below any tolerance the converter
// takes; the converter still verifies its results against R itself.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "designers/convert/polar_function.h"

namespace polarform {

class ProfileTable {
 public:
  // R's nodes are evaluated on every core (task_pool.h): R's derivatives must be safe to call
  // concurrently (every PolarFunction's are: pure functions of immutable data).
  explicit ProfileTable(const PolarFunction& R, int intervals = 4096);

  // R(ψ) and R'(ψ) into out[0..1]; ψ wrapped into the domain (closed) or clamped to it (open).
  // Inline: the fits' inner loops call it for every sample.
  void derivatives(double psi, double* out) const {
    if (!(psi >= start_ && psi <= end_)) psi = wrap(psi);
    const auto k =
        std::min(static_cast<std::size_t>(std::max((psi - start_) * inverse_bucket_width_, 0.0)),
                 bucket_.size() - 1);
    std::size_t i = bucket_[k];
    while (i > 0 && at_[i] > psi) --i;  // k rounded up past a bucket's start
    while (i + 2 < at_.size() && at_[i + 1] <= psi) ++i;
    i = std::min(i, at_.size() - 2);
    const Interval& I = intervals_[i];
    const double t = (psi - at_[i]) * I.inverse_h;
    const double* c = I.c;
    out[0] = c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
    out[1] = (c[1] + t * (2 * c[2] + t * (3 * c[3] + t * (4 * c[4] + t * 5 * c[5])))) * I.inverse_h;
  }
  double operator()(double psi) const {
    double d[2];
    derivatives(psi, d);
    return d[0];
  }
  double wrap(double psi) const;

 private:
  // R on [at_i, at_i+1] as the quintic c_0 + c_1 t + ... + c_5 t^5 in t = (ψ − at_i)/h.
  struct Interval {
    double c[6];
    double inverse_h;  // 1/h, so that a lookup has no division
  };
  double start_, end_;
  bool closed_;
  std::vector<double> at_;
  std::vector<Interval> intervals_;
  double inverse_bucket_width_;
  std::vector<std::size_t> bucket_;  // index of the last node at or before each bucket's start
};

}  // namespace polarform
