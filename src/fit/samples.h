// Scattered samples of a single-valued function: parameters (u_k, v_k), values g_k and optional
// weights w_k. The surface fitters' synchronized points {(ρ_k, u_k, v_k)} (Bae 2002, §3.1 Step 4)
// and a curve's {(r_k, u_k)} (a curve is a 1 x n surface: every u_k is 0) both travel in it.
#pragma once

#include <Eigen/Core>
#include <cstddef>

namespace polarform {

struct Samples {
  Eigen::VectorXd u, v, value;
  Eigen::VectorXd weight;  // empty: every weight is 1

  std::size_t size() const { return static_cast<std::size_t>(value.size()); }
  double w(std::size_t k) const {
    return weight.size() == 0 ? 1.0 : weight[static_cast<Eigen::Index>(k)];
  }
};

// Throws InputError unless u, v, value (and weight, if given) have one entry per sample, every
// entry is finite, weights are >= 0 with a positive sum, and there is at least one sample.
void validate_samples(const Samples& s);

}  // namespace polarform
