// Where the fitted function's breakpoints go: uniformly, or with equal numbers of data parameters
// per span (the averaging rule of the NURBS Book, eq. (9.68)-(9.69), applied to the marginal
// distribution of scattered parameters), and how spans are split when a tolerance is not met.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace polarform {

enum class KnotPlacement { uniform, equal_count };

// spans + 1 breakpoints from a to b (a < b, spans >= 1). equal_count puts the interior breaks at
// quantiles of `params` (values outside [a, b] are clamped), found from a histogram in O(n), then
// keeps every span between half and twice the uniform width, so neither dense data nor gaps
// distort the spline space beyond that.
std::vector<double> place_breaks(KnotPlacement placement, int spans, const Eigen::VectorXd& params,
                                 double a, double b);

// The breaks with span s split at its midpoint wherever split[s] is true.
std::vector<double> split_spans(const std::vector<double>& breaks, const std::vector<bool>& split);

// Index of the span [b_s, b_{s+1}) holding x (the last span holds its end), clamped to the range.
int span_index(const std::vector<double>& breaks, double x);

}  // namespace polarform
