// Knot vectors: validation, span search, multiplicities and breakpoints, standard constructions.
#pragma once

#include <string_view>
#include <vector>

namespace polarform {

using Knots = std::vector<double>;

// Highest degree the kernel evaluates (stack workspaces are sized by it). OCCT's own limit is 25.
inline constexpr int kMaxDegree = 40;

// Throws InputError naming `what` unless: 0 <= degree <= kMaxDegree, knots finite and
// non-decreasing, knots.size() == n + degree + 1 with n >= degree + 1, no interior multiplicity
// above degree + 1 and a non-empty domain [knots[degree], knots[n]].
void validate_knots(int degree, const Knots& knots, int n, std::string_view what);

// Index of the knot span [u_i, u_{i+1}) holding u, clamped to [p, n-1]; NURBS Book A2.1.
int find_span(int degree, const Knots& knots, int n, double u);

// Number of knots equal to u (exact comparison; binary search, knots sorted).
int multiplicity(const Knots& knots, double u);

// Distinct knot values with their multiplicities.
struct Breakpoint {
  double value;
  int multiplicity;
};
std::vector<Breakpoint> breakpoints(const Knots& knots);

// Clamped knot vector of `degree` on [a, b] with the given interior knots (each listed as often
// as its multiplicity).
Knots clamped_knots(int degree, double a, double b, const std::vector<double>& interior = {});

// Clamped knot vector with `spans` equal spans on [a, b].
Knots uniform_clamped_knots(int degree, int spans, double a, double b);

}  // namespace polarform
