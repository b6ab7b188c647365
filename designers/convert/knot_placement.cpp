#include "designers/convert/knot_placement.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace polarform {

// de Boor, A Practical Guide to Splines (1978/2001), ch. XII, NEWNOT; the spans shared among the
// stretches by largest remainder (at least one each).
std::vector<double> equidistribute(const std::vector<double>& breaks,
                                   const std::vector<double>& mass, int spans,
                                   const std::vector<double>& fixed) {
  // The stretches between fixed breaks: their first span of `breaks` and their mass.
  const std::size_t stretches = fixed.size() - 1;
  std::vector<std::size_t> first(stretches + 1, 0);
  std::vector<double> m(stretches, 0.0);
  std::size_t j = 0;
  for (std::size_t s = 0; s < stretches; ++s) {
    first[s] = j;
    while (j + 1 < breaks.size() && breaks[j + 1] <= fixed[s + 1]) m[s] += mass[j++];
  }
  first[stretches] = j;
  const double total = std::accumulate(m.begin(), m.end(), 0.0);
  std::vector<int> n(stretches, 1);
  if (total > 0) {
    std::vector<std::pair<double, std::size_t>> remainder;
    int given = 0;
    for (std::size_t s = 0; s < stretches; ++s) {
      const double ideal = spans * m[s] / total;
      n[s] = std::max(1, static_cast<int>(ideal));
      given += n[s];
      remainder.emplace_back(ideal - n[s], s);
    }
    std::sort(remainder.rbegin(), remainder.rend());
    for (std::size_t r = 0; given < spans && r < remainder.size(); ++r, ++given)
      ++n[remainder[r].second];
  }
  std::vector<double> out{breaks.front()};
  for (std::size_t s = 0; s < stretches; ++s) {
    const double hi = fixed[s + 1];
    // Walk the stretch's cumulative mass, placing a break at every level m·i/n.
    double acc = 0.0;
    std::size_t k = first[s];
    for (int i = 1; i < n[s]; ++i) {
      const double level = m[s] * i / n[s];
      while (k + 1 < first[s + 1] && acc + mass[k] < level) acc += mass[k++];
      const double frac = mass[k] > 0 ? std::clamp((level - acc) / mass[k], 0.0, 1.0) : 0.5;
      const double at = breaks[k] + frac * (breaks[k + 1] - breaks[k]);
      if (at > out.back() && at < hi) out.push_back(at);
    }
    out.push_back(hi);
  }
  return out;
}

}  // namespace polarform
