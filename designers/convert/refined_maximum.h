// Locating the maximum of a one-dimensional error function: dense samples over a grid of
// intervals, then Brent's parabolic-interpolation search (Brent 1973, ch. 5) around the largest
// samples. Used for every error the converter reports.
#pragma once

#include <functional>
#include <vector>

namespace polarform {

struct Maximum {
  double at = 0.0;
  double value = 0.0;
};

// Max of f over [grid.front(), grid.back()]: `per_interval` + 1 samples in each interval of the
// grid, each of the `refine` largest local maxima of the samples refined by Brent's search
// between its neighbours (started from the three samples, to 1e-4 of that bracket).
Maximum refined_maximum(const std::function<double(double)>& f, const std::vector<double>& grid,
                        int per_interval, int refine);

}  // namespace polarform
