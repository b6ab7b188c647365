#include "export/plot_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "export/plot_style.h"
#include "export/text_width.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

namespace style = plot_style;

constexpr double kTitleRow = style::title_font + 12;
constexpr double kUntitledHeader = 14;  // room for a ×10ⁿ factor above the plot area
constexpr double kTickLabelRow = style::tick_length + 4 + style::tick_font + 3;
constexpr double kLabelRow = style::label_font + 9;
constexpr double kStackGap = 6;  // below an upper panel of a shared-x stack
constexpr double kRightMargin = 22;
constexpr double kMinPlotSize = 40;
constexpr double kYMargin = 0.05;        // fraction of the y data range added above and below
constexpr double kMarkerXMargin = 0.03;  // x margin so that end markers clear the frame

struct Extent {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  void include(double v) {
    min = std::min(min, v);
    max = std::max(max, v);
  }
  bool empty() const { return min > max; }
};

bool plottable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

double x_margin(const Plot& plot) {
  const bool markers = std::any_of(plot.series().begin(), plot.series().end(), [](const Series& s) {
    return s.style == Series::Style::markers || s.style == Series::Style::line_markers;
  });
  return markers ? kMarkerXMargin : 0;
}

std::string panel_name(const Plot& plot, std::size_t index) {
  return "panel " + std::to_string(index + 1) +
         (plot.title.empty() ? "" : " ('" + plot.title + "')");
}

// Data of the panel along x (or y): points plottable on both axes, lines, bands, annotations and
// highlights.
Extent data_extent(const Plot& plot, bool along_x, bool log_x, bool log_y) {
  Extent e;
  const bool log = along_x ? log_x : log_y;
  for (const Series& s : plot.series())
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (plottable(s.x[i], log_x) && plottable(s.y[i], log_y))
        e.include(along_x ? s.x[i] : s.y[i]);
  for (const ReferenceLine& line : along_x ? plot.vertical_lines() : plot.horizontal_lines())
    if (plottable(line.value, log)) e.include(line.value);
  if (along_x)
    for (const Band& band : plot.bands())
      for (const double edge : {band.x0, band.x1})
        if (plottable(edge, log)) e.include(edge);
  for (const Annotation& a : plot.annotations())
    if (plottable(a.x, log_x) && plottable(a.y, log_y)) e.include(along_x ? a.x : a.y);
  for (const Highlight& h : plot.highlights())
    if (plottable(h.x, log_x) && plottable(h.y, log_y)) e.include(along_x ? h.x : h.y);
  return e;
}

// The drawn range for an extent: a default when empty, widened when it is a single value, and
// `margin` of the span (in decades on a log axis) added at both ends.
AxisRange finish_range(Extent e, bool log, double margin, const std::string& what) {
  if (e.empty()) return log ? AxisRange{1, 10} : AxisRange{0, 1};
  double lo = e.min, hi = e.max;
  if (lo == hi) {
    if (log) {
      lo /= std::sqrt(10.0);
      hi *= std::sqrt(10.0);
    } else {
      const double pad = lo == 0 ? 1 : 0.1 * std::abs(lo);
      lo -= pad;
      hi += pad;
    }
  } else if (log) {
    const double factor = std::pow(hi / lo, margin);
    lo /= factor;
    hi *= factor;
  } else {
    const double pad = margin * (hi - lo);
    lo -= pad;
    hi += pad;
  }
  if (!std::isfinite(hi - lo) || (log && !(std::isfinite(std::log10(hi / lo)) && lo > 0)))
    throw InputError(what + ": the data span more than a double can hold");
  return {lo, hi};
}

void check_range(const AxisRange& r, bool log, const std::string& what) {
  if (!(std::isfinite(r.min) && std::isfinite(r.max) && r.min < r.max &&
        std::isfinite(r.max - r.min)))
    throw InputError(what + " must be finite with min < max, got [" + format_round_trip(r.min) +
                     ", " + format_round_trip(r.max) + "]");
  if (log && r.min <= 0)
    throw InputError(what + " must be positive on a log axis, got min " + format_round_trip(r.min));
}

// Widens one range so that a data unit spans the same pixels on both axes.
void equalize(AxisRange& x, AxisRange& y, double width, double height) {
  const double sx = width / (x.max - x.min), sy = height / (y.max - y.min);
  AxisRange& widened = sx > sy ? x : y;
  const double half = 0.5 * (sx > sy ? width / sy : height / sx);
  const double centre = 0.5 * (widened.min + widened.max);
  widened = {centre - half, centre + half};
}

double widest_label(const TickSet& ticks) {
  double widest = 0;
  for (const Tick& t : ticks.major)
    widest = std::max(widest, text_width(t.label, style::tick_font));
  return widest;
}

}  // namespace

std::vector<PanelFrame> lay_out_figure(const Figure& figure, double right_room) {
  const std::deque<Plot>& panels = figure.panels();
  if (panels.empty()) throw InputError("Figure: no panels; call add_panel() first");
  const std::size_t n = panels.size();
  const bool shared = figure.shared_x;
  const Plot& first = panels.front();

  // Ranges.
  std::vector<AxisRange> x_ranges(n), y_ranges(n);
  std::vector<bool> log_x(n);
  Extent shared_extent;
  for (std::size_t i = 0; i < n; ++i) {
    const Plot& p = panels[i];
    const std::string name = panel_name(p, i);
    log_x[i] = shared ? first.log_x : p.log_x;
    if (p.equal_aspect && (log_x[i] || p.log_y))
      throw InputError(name + ": equal_aspect needs linear axes");
    if (p.equal_aspect && shared)
      throw InputError(name + ": equal_aspect cannot be used with shared_x");
    const Extent xe = data_extent(p, true, log_x[i], p.log_y);
    if (!xe.empty()) {
      shared_extent.include(xe.min);
      shared_extent.include(xe.max);
    }
    x_ranges[i] = finish_range(xe, log_x[i], x_margin(p), name + " x");
    y_ranges[i] = p.y_range ? *p.y_range
                            : finish_range(data_extent(p, false, log_x[i], p.log_y), p.log_y,
                                           kYMargin, name + " y");
    if (p.x_range) x_ranges[i] = *p.x_range;
    check_range(x_ranges[i], log_x[i], name + " x_range");
    check_range(y_ranges[i], p.log_y, name + " y_range");
  }
  if (shared) {
    const double margin = std::transform_reduce(
        panels.begin(), panels.end(), 0.0, [](double a, double b) { return std::max(a, b); },
        x_margin);
    const AxisRange common = first.x_range
                                 ? *first.x_range
                                 : finish_range(shared_extent, first.log_x, margin, "shared x");
    std::fill(x_ranges.begin(), x_ranges.end(), common);
  }

  // Rows: figure title, then per panel a header (title or room for a ×10ⁿ factor), the plot
  // area, tick labels and the x label (only the last panel's when x is shared).
  double top = kFigurePadding + (figure.title.empty() ? 0 : style::figure_title_font + 14);
  std::vector<double> headers(n), footers(n);
  double fixed = top + kFigurePadding;
  for (std::size_t i = 0; i < n; ++i) {
    headers[i] = panels[i].title.empty() ? kUntitledHeader : kTitleRow;
    footers[i] = shared && i + 1 < n ? kStackGap : kTickLabelRow + kLabelRow;
    fixed += headers[i] + footers[i];
  }
  const double plot_height = std::floor((figure.height() - fixed) / static_cast<double>(n));
  if (plot_height < kMinPlotSize)
    throw InputError("Figure: height " + format_round_trip(figure.height()) + " px leaves " +
                     format_round_trip(plot_height) + " px per plot for " + std::to_string(n) +
                     " panels; at least " + format_round_trip(kMinPlotSize) + " are needed");

  // Columns: the y labels, the widest y tick label of all panels (so stacked axes align), the
  // plot areas and a right margin. Equal aspect changes y ranges, and so the tick labels, with
  // the width: the left margin grows until the labels fit.
  const bool any_y_label =
      std::any_of(panels.begin(), panels.end(), [](const Plot& p) { return !p.y_label.empty(); });
  const double label_column = any_y_label ? style::label_font + 10 : 0;
  const double right = figure.width() - kRightMargin - right_room;
  std::vector<AxisRange> final_x(n), final_y(n);
  std::vector<TickSet> y_ticks(n);
  const auto left_margin_needed = [&](double left) {
    if (right - left < kMinPlotSize)
      throw InputError("Figure: width " + format_round_trip(figure.width()) +
                       " px leaves no room for the plot next to its y tick labels");
    double widest = 0;
    for (std::size_t i = 0; i < n; ++i) {
      final_x[i] = x_ranges[i];
      final_y[i] = y_ranges[i];
      if (panels[i].equal_aspect) equalize(final_x[i], final_y[i], right - left, plot_height);
      const AxisScale y(final_y[i], panels[i].log_y, plot_height, 0);
      y_ticks[i] = choose_ticks(y, AxisSide::left, panels[i].y_tick_step,
                                panel_name(panels[i], i) + " y_tick_step");
      widest = std::max(widest, widest_label(y_ticks[i]));
    }
    return std::ceil(kFigurePadding + label_column + widest + style::tick_length + 5);
  };
  double left = 0;
  for (double needed = left_margin_needed(left); needed > left; needed = left_margin_needed(left))
    left = needed;

  std::vector<PanelFrame> frames;
  for (std::size_t i = 0; i < n; ++i) {
    const Plot& p = panels[i];
    top += headers[i];
    const PixelRect area{left, top, right, top + plot_height};
    top += plot_height + footers[i];
    const AxisScale x(final_x[i], log_x[i], area.left, area.right);
    const AxisScale y(final_y[i], p.log_y, area.bottom, area.top);
    const Plot& x_owner = shared ? first : p;
    TickSet x_ticks = choose_ticks(x, AxisSide::bottom, x_owner.x_tick_step,
                                   panel_name(x_owner, shared ? 0 : i) + " x_tick_step");
    const bool labelled = !shared || i + 1 == n;
    frames.push_back({area, x, y, std::move(x_ticks), std::move(y_ticks[i]), labelled,
                      labelled ? x_owner.x_label : std::string(), false});
  }
  return frames;
}

}  // namespace polarform
