#include "src/fit/samples.h"

#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

void validate_samples(const Samples& s) {
  const Eigen::Index n = s.value.size();
  if (n == 0) throw InputError("fit samples: no samples, expected at least one");
  if (s.u.size() != n || s.v.size() != n || (s.weight.size() != 0 && s.weight.size() != n))
    throw InputError("fit samples: " + std::to_string(s.u.size()) + " u, " +
                     std::to_string(s.v.size()) + " v, " + std::to_string(s.weight.size()) +
                     " weights for " + std::to_string(n) + " values; expected one of each per value");
  for (Eigen::Index k = 0; k < n; ++k)
    if (!std::isfinite(s.u[k]) || !std::isfinite(s.v[k]) || !std::isfinite(s.value[k]))
      throw InputError("fit samples: sample " + std::to_string(k) + " is not finite");
  if (s.weight.size() != 0) {
    if (!(s.weight.array() >= 0.0).all() || !s.weight.allFinite())
      throw InputError("fit samples: weights must be finite and >= 0");
    if (!(s.weight.sum() > 0.0)) throw InputError("fit samples: weights sum to 0, expected > 0");
  }
}

}  // namespace polarform
