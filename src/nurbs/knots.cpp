#include "src/nurbs/knots.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "src/error.h"

namespace polarform {

void validate_knots(int degree, const Knots& knots, int n, std::string_view what) {
  auto fail = [&](const std::string& why) {
    std::ostringstream msg;
    msg << what << ": " << why;
    throw InputError(msg.str());
  };
  if (degree < 0 || degree > kMaxDegree)
    fail("degree " + std::to_string(degree) + " outside [0, " + std::to_string(kMaxDegree) + "]");
  if (n < degree + 1)
    fail(std::to_string(n) + " control values, need at least degree+1 = " + std::to_string(degree + 1));
  if (static_cast<int>(knots.size()) != n + degree + 1)
    fail(std::to_string(knots.size()) + " knots, expected control values + degree + 1 = " +
         std::to_string(n + degree + 1));
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i])) fail("knot " + std::to_string(i) + " is not finite");
    if (i > 0 && knots[i] < knots[i - 1])
      fail("knots not non-decreasing at index " + std::to_string(i));
  }
  if (!(knots[degree] < knots[n])) fail("empty parameter domain [u_p, u_n]");
  for (const Breakpoint& b : breakpoints(knots))
    if (b.multiplicity > degree + 1)
      fail("knot " + std::to_string(b.value) + " has multiplicity " + std::to_string(b.multiplicity) +
           " > degree + 1");
}

int find_span(int degree, const Knots& knots, int n, double u) {
  if (u >= knots[n]) {
    // Skip zero-length spans at the end of the domain.
    int span = n - 1;
    while (span > degree && knots[span] >= knots[n]) --span;
    return span;
  }
  if (u <= knots[degree]) {
    // Skip zero-length spans at the start of the domain.
    int span = degree;
    while (span < n - 1 && knots[span + 1] <= u) ++span;
    return span;
  }
  auto it = std::upper_bound(knots.begin() + degree, knots.begin() + n + 1, u);
  return static_cast<int>(it - knots.begin()) - 1;
}

int multiplicity(const Knots& knots, double u) {
  const auto [first, last] = std::equal_range(knots.begin(), knots.end(), u);
  return static_cast<int>(last - first);
}

std::vector<Breakpoint> breakpoints(const Knots& knots) {
  std::vector<Breakpoint> out;
  for (double k : knots) {
    if (!out.empty() && out.back().value == k)
      ++out.back().multiplicity;
    else
      out.push_back({k, 1});
  }
  return out;
}

Knots clamped_knots(int degree, double a, double b, const std::vector<double>& interior) {
  Knots knots(degree + 1, a);
  knots.insert(knots.end(), interior.begin(), interior.end());
  knots.insert(knots.end(), degree + 1, b);
  return knots;
}

Knots uniform_clamped_knots(int degree, int spans, double a, double b) {
  std::vector<double> interior;
  for (int i = 1; i < spans; ++i) interior.push_back(a + (b - a) * i / spans);
  return clamped_knots(degree, a, b, interior);
}

}  // namespace polarform
