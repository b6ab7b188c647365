// Locating the maximum of a one-dimensional error function: dense samples over a grid of
// intervals, then golden-section refinement (Kiefer 1953) around the largest samples. Used for
// every error the converter reports.
#pragma once

#include <functional>
#include <vector>

namespace polarform {

struct Maximum {
  double at = 0.0;
  double value = 0.0;
};

// Max of f over [grid.front(), grid.back()]: `per_interval` + 1 samples in each interval of the
// grid, each of the `refine` largest local maxima of the samples refined by golden section
// between its neighbours.
Maximum refined_maximum(const std::function<double(double)>& f, const std::vector<double>& grid,
                        int per_interval, int refine);

}  // namespace polarform
