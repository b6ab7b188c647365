// One axis of a plot panel: the data-to-pixel transform (linear or log10) and the choice of
// ticks, the densest nice set whose labels stay clear of each other at the axis's pixel length
// (horizontal labels need their width plus a gap, vertical ones a line of text).
#pragma once

#include <optional>
#include <string_view>

#include "export/figure.h"
#include "export/nice_ticks.h"

namespace polarform {

class AxisScale {
 public:
  // Maps range.min to pixel_from and range.max to pixel_to (log: 0 < min < max).
  AxisScale(AxisRange range, bool log, double pixel_from, double pixel_to);

  // Pixel coordinate of v; NaN if v is not finite, or not positive on a log axis.
  double operator()(double v) const;

  const AxisRange& range() const { return range_; }
  bool log() const { return log_; }
  double pixel_from() const { return from_; }
  double pixel_to() const { return to_; }

 private:
  AxisRange range_;
  bool log_;
  double from_, to_;
  double origin_, pixels_per_unit_;  // in log10 units on a log axis
};

enum class AxisSide { bottom, left };

// Ticks for the axis; with a step (linear axes only) the multiples of it. field names the step
// setting in error messages ("x_tick_step").
TickSet choose_ticks(const AxisScale& scale, AxisSide side, std::optional<double> step,
                     std::string_view field);

}  // namespace polarform
