#include "designers/convert/knot_placement.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace polarform {

// de Boor, A Practical Guide to Splines (1978/2001), ch. XII, NEWNOT.
std::vector<double> equidistribute(const std::vector<double>& breaks,
                                   const std::vector<double>& mass, int spans,
                                   const std::vector<double>& fixed) {
  const double total = std::accumulate(mass.begin(), mass.end(), 0.0);
  std::vector<double> out{breaks.front()};
  std::size_t j = 0;  // current span of `breaks`
  for (std::size_t s = 0; s + 1 < fixed.size(); ++s) {
    const double lo = fixed[s], hi = fixed[s + 1];
    // The stretch's spans [j0, j1) and their mass.
    const std::size_t j0 = j;
    while (j + 1 < breaks.size() && breaks[j + 1] <= hi) ++j;
    const std::size_t j1 = j;
    const double m = std::accumulate(mass.begin() + static_cast<std::ptrdiff_t>(j0),
                                     mass.begin() + static_cast<std::ptrdiff_t>(j1), 0.0);
    const int n = total > 0 ? std::max(1, static_cast<int>(std::lround(spans * m / total))) : 1;
    // Walk the cumulative mass, placing a break at every level m·i/n.
    double acc = 0.0;
    std::size_t k = j0;
    for (int i = 1; i < n; ++i) {
      const double level = m * i / n;
      while (k + 1 < j1 && acc + mass[k] < level) acc += mass[k++];
      const double frac = mass[k] > 0 ? std::clamp((level - acc) / mass[k], 0.0, 1.0) : 0.5;
      const double at = breaks[k] + frac * (breaks[k + 1] - breaks[k]);
      if (at > out.back() && at < hi) out.push_back(at);
    }
    (void)lo;
    out.push_back(hi);
  }
  return out;
}

}  // namespace polarform
