#include "src/fit/coefficient_map.h"

#include <string>

#include "src/error.h"

namespace polarform {

CoefficientMap::CoefficientMap(int nu, int nv, int v_period, int pole_start, int pole_end)
    : nu_(nu), nv_(nv) {
  if (nu < 1 || nv < 1)
    throw InputError("coefficient map: net " + std::to_string(nu) + " x " + std::to_string(nv) +
                     ", expected at least 1 x 1");
  if (v_period < 0 || v_period > nv)
    throw InputError("coefficient map: period " + std::to_string(v_period) + ", expected 0.." +
                     std::to_string(nv));
  if (pole_start < 0 || pole_start > 2 || pole_end < 0 || pole_end > 2 || pole_start + pole_end > nu)
    throw InputError("coefficient map: pole rows " + std::to_string(pole_start) + " + " +
                     std::to_string(pole_end) + " for " + std::to_string(nu) +
                     " rows; expected 0..2 each, at most the rows along u");
  map_.assign(static_cast<std::size_t>(nu) * nv, -1);
  const int distinct_v = v_period > 0 ? v_period : nv;
  const int start_pole = pole_start > 0 ? unknowns_++ : -1;
  int end_pole = -1;
  for (int i = 0; i < nu; ++i) {
    const bool in_start = i < pole_start, in_end = i >= nu - pole_end;
    if (in_end && end_pole < 0) end_pole = unknowns_++;
    for (int j = 0; j < nv; ++j) {
      int& m = map_[static_cast<std::size_t>(i * nv + j)];
      if (in_start) m = start_pole;                                               // (3.14)
      else if (in_end) m = end_pole;                                              // (3.14)
      else if (j >= distinct_v) m = map_[static_cast<std::size_t>(i * nv + j % distinct_v)];  // (3.10)
      else m = unknowns_++;
    }
  }
}

Eigen::VectorXd CoefficientMap::expand(const Eigen::VectorXd& unknowns) const {
  if (unknowns.size() != unknowns_)
    throw InputError("coefficient map: " + std::to_string(unknowns.size()) + " unknowns, expected " +
                     std::to_string(unknowns_));
  Eigen::VectorXd full(static_cast<Eigen::Index>(map_.size()));
  for (std::size_t k = 0; k < map_.size(); ++k) full[static_cast<Eigen::Index>(k)] = unknowns[map_[k]];
  return full;
}

}  // namespace polarform
