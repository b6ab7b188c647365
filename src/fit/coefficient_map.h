// Equality constraints of the single-valued fit solved by elimination: every coefficient f_ij of
// the tensor-product net (index i·nv + j, i along u) maps to one unknown. Periodicity identifies
// f_{i,j} with f_{i,j mod K} (Bae 2002, eq. (3.10)); at a pole, row 0 (G0, eq. (3.14a)) or rows 0
// and 1 (the simple G1 condition, eqs. (3.14a-b)) become one unknown, likewise the last rows at the
// other pole. The normal equations are assembled
// directly in the unknowns, so the constrained system stays sparse and positive definite.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace polarform {

class CoefficientMap {
 public:
  // nu x nv net; v_period > 0 identifies column j with j mod v_period (v_period <= nv);
  // pole_start / pole_end (0, 1 or 2) tie that many first / last rows to one unknown each
  // (needs nu >= pole_start + pole_end).
  CoefficientMap(int nu, int nv, int v_period = 0, int pole_start = 0, int pole_end = 0);

  int size_u() const { return nu_; }
  int size_v() const { return nv_; }
  int full_size() const { return nu_ * nv_; }
  int unknowns() const { return unknowns_; }
  // The unknown of coefficient (i, j).
  int operator()(int i, int j) const { return map_[static_cast<std::size_t>(i * nv_ + j)]; }
  int operator[](int full) const { return map_[static_cast<std::size_t>(full)]; }

  // The full net (nu·nv values, i·nv + j) from the unknowns.
  Eigen::VectorXd expand(const Eigen::VectorXd& unknowns) const;

 private:
  int nu_, nv_, unknowns_ = 0;
  std::vector<int> map_;
};

}  // namespace polarform
