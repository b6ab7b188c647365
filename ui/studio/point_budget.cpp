#include "ui/studio/point_budget.h"

#include <algorithm>
#include <cmath>

namespace polarform::studio {

void PointBudget::adapt(double seconds, int total) {
  const int ceiling = std::max(total, kMinimum);
  if (!(seconds > 0.0)) return;
  // Damped multiplicative control: frame time is about linear in the points drawn.
  const double factor = std::clamp(std::sqrt(kTargetSeconds / seconds), 0.8, 1.25);
  const double next = std::min<double>(points_, ceiling) * factor;
  points_ = static_cast<int>(std::clamp<double>(std::round(next), kMinimum, ceiling));
}

}  // namespace polarform::studio
