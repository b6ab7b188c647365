// Knot placement by need: de Boor's equidistribution (A Practical Guide to Splines, ch. XII,
// NEWNOT), on a density given by its mass over each span of the current breaks (for a
// degree-p fit the measured span error^(1/(p+1)), since the error scales like h^(p+1)).
#pragma once

#include <vector>

namespace polarform {

// New breaks b_0 = breaks.front() < ... < breaks.back() with about `spans` spans that give each
// span an equal share of the piecewise-constant density of mass[j] on [breaks[j], breaks[j+1]].
// Every value of `fixed` (a subset of `breaks`, including both ends) stays a break; the stretches
// between them get spans in proportion to their mass, at least one each.
std::vector<double> equidistribute(const std::vector<double>& breaks,
                                   const std::vector<double>& mass, int spans,
                                   const std::vector<double>& fixed);

}  // namespace polarform
