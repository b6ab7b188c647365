#include "export/plot_axis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "export/plot_style.h"
#include "export/text_width.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

constexpr int kMaxTicks = 200;

double transformed(double v, bool log) { return log ? std::log10(v) : v; }

// Neighbouring labels must not touch: horizontal ones need half of each width plus a gap,
// stacked ones a line of text plus a gap.
bool labels_fit(const TickSet& ticks, const AxisScale& scale, AxisSide side) {
  for (std::size_t i = 1; i < ticks.major.size(); ++i) {
    const double distance = std::abs(scale(ticks.major[i].value) - scale(ticks.major[i - 1].value));
    const double needed =
        side == AxisSide::left
            ? plot_style::tick_font + 4
            : 0.5 * (text_width(ticks.major[i].label, plot_style::tick_font) +
                     text_width(ticks.major[i - 1].label, plot_style::tick_font)) +
                  12;
    if (distance < needed) return false;
  }
  return true;
}

TickSet choose_linear_ticks(const AxisScale& scale, AxisSide side) {
  const double lo = scale.range().min, hi = scale.range().max;
  const double target_spacing = side == AxisSide::left ? 40 : 75;  // px between ticks, roughly
  const double length = std::abs(scale.pixel_to() - scale.pixel_from());
  // Clamped so that extreme spans (subnormal, near DBL_MAX) still give a finite step.
  const double raw =
      std::clamp((hi - lo) / length * target_spacing, std::numeric_limits<double>::min(), 1e300);
  int index = nice_step_index(raw);
  TickSet ticks = linear_ticks(lo, hi, nice_step(index));
  while (!labels_fit(ticks, scale, side)) ticks = linear_ticks(lo, hi, nice_step(++index));
  // A short axis may have room for two ticks of a finer step rather than one.
  for (int finer = 0; ticks.major.size() < 2 && finer < 6; ++finer) {
    TickSet denser = linear_ticks(lo, hi, nice_step(--index));
    if (!labels_fit(denser, scale, side)) break;
    ticks = std::move(denser);
  }
  return ticks;
}

// Decades, every stride-th one when the labels are crowded; 2..9 minor ticks only where a
// decade is wide enough to show them.
TickSet choose_decade_ticks(const AxisScale& scale, AxisSide side) {
  const double lo = scale.range().min, hi = scale.range().max;
  TickSet ticks;
  for (const int stride : {1, 2, 3, 5, 10, 20, 50, 100}) {
    ticks = log_decade_ticks(lo, hi, stride);
    if (labels_fit(ticks, scale, side)) break;
  }
  if (std::abs(scale(10 * lo) - scale(lo)) < 25)
    std::erase_if(ticks.minor, [](double v) {
      return std::abs(std::log10(v) - std::round(std::log10(v))) > 1e-9;
    });
  return ticks;
}

// Three or more decades: decades. Narrower ranges: 1-2-5 (or 1..9) mantissas while they fit and
// give at least three labels, else two decades, else whatever gives two labels.
TickSet choose_log_ticks(const AxisScale& scale, AxisSide side) {
  const double lo = scale.range().min, hi = scale.range().max;
  const std::size_t decades = log_decade_ticks(lo, hi, 1).major.size();
  if (decades >= 3) return choose_decade_ticks(scale, side);
  static constexpr int one_two_five[] = {1, 2, 5}, all[] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  const std::span<const int> mantissa_sets[] = {one_two_five, all};
  for (const std::size_t wanted : {3, 2}) {
    if (wanted == 2 && decades == 2) return choose_decade_ticks(scale, side);
    for (const std::span<const int> mantissas : mantissa_sets) {
      TickSet ticks = log_mantissa_ticks(lo, hi, mantissas);
      if (ticks.major.size() >= wanted && labels_fit(ticks, scale, side)) return ticks;
    }
  }
  return choose_linear_ticks(scale, side);
}

}  // namespace

AxisScale::AxisScale(AxisRange range, bool log, double pixel_from, double pixel_to)
    : range_(range),
      log_(log),
      from_(pixel_from),
      to_(pixel_to),
      origin_(transformed(range.min, log)),
      pixels_per_unit_((pixel_to - pixel_from) /
                       (transformed(range.max, log) - transformed(range.min, log))) {}

double AxisScale::operator()(double v) const {
  if (!std::isfinite(v) || (log_ && v <= 0)) return std::numeric_limits<double>::quiet_NaN();
  return from_ + (transformed(v, log_) - origin_) * pixels_per_unit_;
}

TickSet choose_ticks(const AxisScale& scale, AxisSide side, std::optional<double> step,
                     std::string_view field) {
  if (!step) return scale.log() ? choose_log_ticks(scale, side) : choose_linear_ticks(scale, side);
  const std::string name(field);
  if (scale.log()) throw InputError(name + " applies to linear axes only; the axis is logarithmic");
  if (!(std::isfinite(*step) && *step > 0))
    throw InputError(name + " must be a positive number, got " + format_round_trip(*step));
  const double lo = scale.range().min, hi = scale.range().max;
  if ((hi - lo) / *step > kMaxTicks)
    throw InputError(name + " " + format_round_trip(*step) + " gives more than " +
                     std::to_string(kMaxTicks) + " ticks on [" + format_round_trip(lo) + ", " +
                     format_round_trip(hi) + "]");
  return linear_ticks(lo, hi, *step);
}

}  // namespace polarform
