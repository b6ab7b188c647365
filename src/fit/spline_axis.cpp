#include "src/fit/spline_axis.h"

#include <string>

#include "src/error.h"
#include "src/nurbs/periodic.h"

namespace polarform {

std::vector<double> SplineAxis::breaks() const {
  std::vector<double> out;
  for (int i = degree; i <= size(); ++i)
    if (out.empty() || knots[i] > out.back()) out.push_back(knots[i]);
  return out;
}

SplineAxis clamped_axis(int degree, const std::vector<double>& breaks) {
  if (breaks.size() < 2)
    throw InputError("fit axis: " + std::to_string(breaks.size()) + " breakpoints, expected >= 2");
  const std::vector<double> interior(breaks.begin() + 1, breaks.end() - 1);
  SplineAxis axis{degree, clamped_knots(degree, breaks.front(), breaks.back(), interior), false};
  validate_knots(degree, axis.knots, axis.size(), "fit axis");
  return axis;
}

SplineAxis periodic_axis(int degree, const std::vector<double>& breaks) {
  const int spans = static_cast<int>(breaks.size()) - 1;
  if (spans < degree + 1)
    throw InputError("periodic fit axis: " + std::to_string(spans) + " spans for degree " +
                     std::to_string(degree) + ", expected at least " + std::to_string(degree + 1));
  return SplineAxis{degree, periodic_knots(degree, breaks), true};
}

}  // namespace polarform
