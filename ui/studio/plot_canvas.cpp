#include "ui/studio/plot_canvas.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "export/plot_axis.h"
#include "export/plot_style.h"
#include "export/polyline_path.h"
#include "src/number_text.h"
#include "ui/studio/colors.h"
#include "ui/studio/opaque_fill.h"
#include "ui/studio/polyline_simplify.h"

namespace polarform::studio {
namespace {

constexpr double kTickFont = plot_style::tick_font;  // the font choose_ticks assumes
constexpr float kLineWidth = 2.0f;  // whole pixels: ImGui draws those as cheap textured lines

// The x-axis settings a panel draws with: its own, or the first panel's on a shared axis.
struct XAxis {
  bool log = false;
  std::optional<AxisRange> extent;  // what "fit" shows; default: the data
  const std::string* label = nullptr;
  bool tick_labels = true;
  std::optional<double> tick_step;
};

double forward(double v, bool log) { return log ? std::log10(v) : v; }
double backward(double t, bool log) { return log ? std::pow(10.0, t) : t; }

bool usable(const AxisRange& r, bool log) {
  if (!std::isfinite(r.min) || !std::isfinite(r.max) || !(r.max > r.min)) return false;
  if (log && !(r.min > 0)) return false;
  const double a = forward(r.min, log), b = forward(r.max, log);
  return b - a > 1e-12 * std::max(1.0, std::max(std::abs(a), std::abs(b)));
}

// Widens a range by `margin` of its span on both sides (in log10 units on a log axis); a
// degenerate range becomes a small one around its value.
AxisRange padded(AxisRange r, bool log, double margin) {
  double a = forward(r.min, log), b = forward(r.max, log);
  if (!(b - a > 1e-12 * std::max(1.0, std::abs(a)))) {
    const double half = log ? 0.5 : std::max(0.5 * std::abs(a), 0.5);
    a -= half;
    b += half;
  }
  const double pad = margin * (b - a);
  return {backward(a - pad, log), backward(b + pad, log)};
}

struct Extent {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v, bool log) {
    if (!std::isfinite(v) || (log && v <= 0)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(hi >= lo); }
};

void add_x_data(Extent& e, const Plot& plot, bool log) {
  for (const Series& s : plot.series())
    for (double x : s.x) e.add(x, log);
  for (const Highlight& h : plot.highlights()) e.add(h.x, log);
}

AxisRange fit_x(const Extent& e, bool log) {
  if (e.empty()) return log ? AxisRange{0.1, 10.0} : AxisRange{0.0, 1.0};
  return e.hi > e.lo ? AxisRange{e.lo, e.hi} : padded({e.lo, e.hi}, log, 0.05);
}

AxisRange fit_y(const Plot& plot, const AxisRange& x) {
  if (plot.y_range) return *plot.y_range;
  Extent e;
  for (const Series& s : plot.series()) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t i = 0; i < n; ++i)
      if (s.x[i] >= x.min && s.x[i] <= x.max) e.add(s.y[i], plot.log_y);
  }
  for (const ReferenceLine& level : plot.horizontal_lines()) e.add(level.value, plot.log_y);
  for (const Highlight& h : plot.highlights())
    if (h.x >= x.min && h.x <= x.max) e.add(h.y, plot.log_y);
  if (e.empty()) return plot.log_y ? AxisRange{0.1, 10.0} : AxisRange{0.0, 1.0};
  return padded({e.lo, e.hi}, plot.log_y, 0.05);
}

// Equal aspect: the range with fewer units per pixel widened about its centre to match the other.
void equalise(AxisRange& x, AxisRange& y, double width, double height) {
  const double ux = (x.max - x.min) / width, uy = (y.max - y.min) / height;
  if (!(ux > 0 && uy > 0)) return;
  if (ux < uy) {
    const double c = 0.5 * (x.min + x.max), half = 0.5 * uy * width;
    x = {c - half, c + half};
  } else {
    const double c = 0.5 * (y.min + y.max), half = 0.5 * ux * height;
    y = {c - half, c + half};
  }
}

// The range zoomed by `factor` about `center` (a data value), in log10 units on a log axis.
AxisRange zoomed(const AxisRange& r, bool log, double center, double factor) {
  const double c = forward(center, log);
  const AxisRange z{backward(c + (forward(r.min, log) - c) * factor, log),
                    backward(c + (forward(r.max, log) - c) * factor, log)};
  return usable(z, log) ? z : r;
}

// The range moved by `pixels` on an axis of `length` pixels.
AxisRange panned(const AxisRange& r, bool log, double pixels, double length) {
  const double a = forward(r.min, log), b = forward(r.max, log);
  const double shift = -pixels * (b - a) / length;
  const AxisRange p{backward(a + shift, log), backward(b + shift, log)};
  return usable(p, log) ? p : r;
}

double to_data(const AxisScale& s, double pixel) {
  const double f = (pixel - s.pixel_from()) / (s.pixel_to() - s.pixel_from());
  const double a = forward(s.range().min, s.log()), b = forward(s.range().max, s.log());
  return backward(a + f * (b - a), s.log());
}

// Ticks chosen as if the labels were set in export/plot_style's font: the axis length is scaled
// by the ratio of the fonts, so spacing decisions carry over to ImGui's font size. The figure's
// own step (30° on cam angles) is kept while it gives between 3 and 16 ticks.
TickSet ticks_for(const AxisRange& range, bool log, double length, AxisSide side,
                  std::optional<double> step = std::nullopt) {
  const double font = ImGui::GetFontSize();
  const AxisScale layout(range, log, 0.0, length * kTickFont / font);
  if (step && !log && *step > 0) {
    const double count = (range.max - range.min) / *step;
    if (count >= 2 && count <= 15) return choose_ticks(layout, side, step, "ticks");
  }
  return choose_ticks(layout, side, std::nullopt, "ticks");
}

ImU32 color_or(const std::string& hex, ImU32 fallback, float alpha = 1.0f) {
  return hex.empty() ? fallback : hex_color(hex.c_str(), alpha);
}

// Each series' colour: its own, or the next palette colour (as the SVG writer assigns them).
std::vector<ImU32> series_colors(const Plot& plot) {
  std::vector<ImU32> colors;
  int palette = 0;
  for (const Series& s : plot.series())
    colors.push_back(s.color.empty() ? palette_color(palette++) : hex_color(s.color.c_str()));
  return colors;
}

bool draws_line(Series::Style s) { return s != Series::Style::markers; }
bool draws_markers(Series::Style s) {
  return s == Series::Style::markers || s == Series::Style::line_markers;
}

// Index of the sample of `s` nearest to x, for series sorted by x; none for scattered markers.
std::optional<std::size_t> nearest(const Series& s, double x) {
  const std::size_t n = std::min(s.x.size(), s.y.size());
  if (n == 0 || s.style == Series::Style::markers) return std::nullopt;
  const auto it = std::lower_bound(s.x.begin(), s.x.begin() + static_cast<std::ptrdiff_t>(n), x);
  std::size_t i = static_cast<std::size_t>(it - s.x.begin());
  if (i == n) return n - 1;
  if (i > 0 && std::abs(s.x[i - 1] - x) < std::abs(s.x[i] - x)) --i;
  return i;
}

// A polyline in dashes of 6 px with gaps of 4 px, measured along the line.
void add_dashed(ImDrawList* dl, const std::vector<ImVec2>& points, ImU32 color) {
  bool on = true;
  float left = 6.0f;
  for (std::size_t i = 1; i < points.size(); ++i) {
    ImVec2 a = points[i - 1];
    const ImVec2 b = points[i];
    float length = std::hypot(b.x - a.x, b.y - a.y);
    while (length > 0.0f) {
      const float step = std::min(left, length);
      const float f = step / length;
      const ImVec2 c(a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f);
      if (on) dl->AddLine(a, c, color, kLineWidth);
      a = c;
      length -= step;
      left -= step;
      if (left <= 0.0f) {
        on = !on;
        left = on ? 6.0f : 4.0f;
      }
    }
  }
}

void draw_series(ImDrawList* dl, const Series& s, ImU32 color, const AxisScale& sx,
                 const AxisScale& sy, const ImVec2& clip_min, const ImVec2& clip_max) {
  const std::size_t n = std::min(s.x.size(), s.y.size());
  if (n == 0) return;
  std::vector<PixelPoint> pixels;
  pixels.reserve(n);
  if (s.style == Series::Style::markers) {
    for (std::size_t i = 0; i < n; ++i) pixels.push_back({sx(s.x[i]), sy(s.y[i])});
  } else {  // sorted by x: only the samples inside the visible x range, plus one on each side
    const auto begin = s.x.begin(), end = s.x.begin() + static_cast<std::ptrdiff_t>(n);
    const auto first = std::lower_bound(begin, end, sx.range().min);
    const auto last = std::upper_bound(first, end, sx.range().max);
    const std::size_t i0 = static_cast<std::size_t>(std::max<std::ptrdiff_t>(first - begin - 1, 0));
    const std::size_t i1 = std::min(n, static_cast<std::size_t>(last - begin) + 1);
    for (std::size_t i = i0; i < i1; ++i) pixels.push_back({sx(s.x[i]), sy(s.y[i])});
  }
  const float dot = ImGui::GetFontSize() * 0.18f;
  std::vector<ImVec2> points;
  for (const Polyline& run : finite_runs(pixels)) {
    if (draws_markers(s.style)) {
      int last_x = std::numeric_limits<int>::min(), last_y = last_x;
      for (const PixelPoint& p : run) {  // one dot per pixel
        const int px = static_cast<int>(std::lround(p.x)), py = static_cast<int>(std::lround(p.y));
        if ((px == last_x && py == last_y) || p.x < clip_min.x || p.x > clip_max.x ||
            p.y < clip_min.y || p.y > clip_max.y)
          continue;
        dl->AddCircleFilled(ImVec2(static_cast<float>(p.x), static_cast<float>(p.y)), dot, color,
                            6);
        last_x = px;
        last_y = py;
      }
    }
    if (!draws_line(s.style)) continue;
    const Polyline thin = simplify_polyline(decimate_to_columns(run));
    points.clear();
    for (const PixelPoint& p : thin)
      points.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
    if (points.size() == 1) points.push_back(points.front());
    if (s.style == Series::Style::dashed)
      add_dashed(dl, points, color);
    else
      dl->AddPolyline(points.data(), static_cast<int>(points.size()), color, 0, kLineWidth);
  }
}

// The draggable vertical line within `reach` pixels of the mouse inside the plot, or -1.
int nearest_draggable(const Plot& plot, const AxisScale& sx, ImVec2 mouse, float reach, float top,
                      float bottom) {
  if (!ImGui::IsItemHovered() || mouse.y < top || mouse.y > bottom) return -1;
  int best = -1;
  double best_distance = reach;
  const auto& lines = plot.vertical_lines();
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    if (lines[i].handle < 0) continue;
    const double d = std::abs(sx(lines[i].value) - mouse.x);
    if (d <= best_distance) {
      best = i;
      best_distance = d;
    }
  }
  return best;
}

// A legend in the plot's top-right corner when two or more series or bands carry labels.
void draw_legend(ImDrawList* dl, const Plot& plot, const std::vector<ImU32>& colors,
                 ImVec2 top_right, float fh) {
  struct Entry {
    const std::string* label;
    ImU32 color;
    bool band;
  };
  std::vector<Entry> entries;
  float width = 0.0f;
  for (std::size_t k = 0; k < plot.series().size(); ++k)
    if (!plot.series()[k].label.empty())
      entries.push_back({&plot.series()[k].label, colors[k], false});
  for (const Band& b : plot.bands())
    if (!b.label.empty())
      entries.push_back({&b.label, color_or(b.color, color::boundary, 0.35f), true});
  for (const Entry& e : entries) width = std::max(width, ImGui::CalcTextSize(e.label->c_str()).x);
  if (entries.size() < 2) return;
  const float swatch = fh * 1.5f, pad = fh * 0.3f;
  const ImVec2 min(top_right.x - width - swatch - 3 * pad, top_right.y + pad);
  const ImVec2 max(top_right.x - pad, min.y + entries.size() * fh + 2 * pad);
  dl->AddRectFilled(min, max, IM_COL32(255, 255, 255, 215));
  dl->AddRect(min, max, color::frame);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const float y = min.y + pad + k * fh;
    if (entries[k].band)
      dl->AddRectFilled(ImVec2(min.x + pad, y + fh * 0.2f),
                        ImVec2(min.x + pad + swatch, y + fh * 0.8f), entries[k].color);
    else
      dl->AddLine(ImVec2(min.x + pad, y + fh * 0.5f), ImVec2(min.x + pad + swatch, y + fh * 0.5f),
                  entries[k].color, kLineWidth);
    dl->AddText(ImVec2(min.x + 2 * pad + swatch, y), color::text, entries[k].label->c_str());
  }
}

PlotEvents draw_panel(const char* id, const Plot& plot, const XAxis& xa, AxisView& x_view,
                      AxisView& y_view, ImVec2 size, Crosshair* crosshair) {
  PlotEvents events;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  size.x = std::max(size.x, 120.0f);
  size.y = std::max(size.y, 80.0f);
  const ImGuiID drag_key = ImGui::GetID(id);
  ImGui::InvisibleButton(id, size);
  const bool hovered = ImGui::IsItemHovered();
  const bool active = ImGui::IsItemActive();
  const bool activated = ImGui::IsItemActivated();
  const ImGuiIO& io = ImGui::GetIO();
  const float fh = ImGui::GetFontSize();
  const std::string& x_label = *xa.label;

  // Layout: title line on top (title, y label), tick labels and x label below, y ticks left.
  const float top = origin.y + fh * 1.5f;
  const float bottom =
      origin.y + size.y - (xa.tick_labels ? fh * (x_label.empty() ? 1.5f : 2.7f) : fh * 0.5f);
  if (x_view.range && !usable(*x_view.range, xa.log)) x_view.range.reset();
  if (y_view.range && !usable(*y_view.range, plot.log_y)) y_view.range.reset();
  AxisRange xr = x_view.range ? *x_view.range : *xa.extent;
  AxisRange yr = y_view.range ? *y_view.range : fit_y(plot, xr);
  const TickSet ytick_guess =
      ticks_for(yr, plot.log_y, std::max(10.0f, bottom - top), AxisSide::left);
  float label_width = 0.0f;
  for (const Tick& t : ytick_guess.major)
    label_width = std::max(label_width, ImGui::CalcTextSize(t.label.c_str()).x);
  const float left = origin.x + label_width + fh * 0.8f;
  const float right = origin.x + size.x - fh * 0.8f;
  if (right - left < 20.0f || bottom - top < 20.0f) return events;
  if (plot.equal_aspect && !xa.log && !plot.log_y) equalise(xr, yr, right - left, bottom - top);
  const AxisScale sx(xr, xa.log, left, right);
  const AxisScale sy(yr, plot.log_y, bottom, top);
  const TickSet xticks = ticks_for(xr, xa.log, right - left, AxisSide::bottom, xa.tick_step);
  const TickSet yticks = ticks_for(yr, plot.log_y, bottom - top, AxisSide::left, plot.y_tick_step);

  // Input: a draggable line under the mouse follows it; otherwise zoom about the cursor (over an
  // axis: that axis only), drag to pan, double-click to fit.
  const ImVec2 mouse = io.MousePos;
  ImGuiStorage* storage = ImGui::GetStateStorage();
  const int near_line = nearest_draggable(plot, sx, mouse, fh * 0.4f, top, bottom);
  if (activated) storage->SetInt(drag_key, near_line);
  const int dragging = active ? storage->GetInt(drag_key, -1) : -1;
  if (!active) storage->SetInt(drag_key, -1);
  if (dragging >= 0 && dragging < static_cast<int>(plot.vertical_lines().size())) {
    events.dragged_handle = plot.vertical_lines()[dragging].handle;
    events.value = std::clamp(to_data(sx, mouse.x), xr.min, xr.max);
  }
  if (near_line >= 0 || dragging >= 0) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  if (hovered && io.MouseWheel != 0.0f) {
    const double factor = std::pow(0.85, io.MouseWheel);
    const bool over_y_axis = mouse.x<left, over_x_axis = mouse.y> bottom;
    if (!over_y_axis) x_view.range = zoomed(xr, xa.log, to_data(sx, mouse.x), factor);
    if (!over_x_axis) y_view.range = zoomed(yr, plot.log_y, to_data(sy, mouse.y), factor);
  }
  if (dragging < 0 && active && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 1.0f)) {
    if (io.MouseDelta.x != 0.0f) x_view.range = panned(xr, xa.log, io.MouseDelta.x, right - left);
    if (io.MouseDelta.y != 0.0f)
      y_view.range = panned(yr, plot.log_y, -io.MouseDelta.y, bottom - top);
  }
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    x_view.range.reset();
    y_view.range.reset();
  }

  // Frame, grid, ticks.
  add_opaque_rect(dl, ImVec2(left, top), ImVec2(right, bottom), color::background);
  for (double v : yticks.minor)
    dl->AddLine(ImVec2(left, sy(v)), ImVec2(right, sy(v)), color::minor_grid);
  for (double v : xticks.minor)
    dl->AddLine(ImVec2(sx(v), top), ImVec2(sx(v), bottom), color::minor_grid);
  for (const Tick& t : yticks.major) {
    const float y = static_cast<float>(sy(t.value));
    dl->AddLine(ImVec2(left, y), ImVec2(right, y), color::grid);
    const ImVec2 ts = ImGui::CalcTextSize(t.label.c_str());
    dl->AddText(ImVec2(left - ts.x - fh * 0.35f, y - ts.y * 0.5f), color::text, t.label.c_str());
  }
  for (const Tick& t : xticks.major) {
    const float x = static_cast<float>(sx(t.value));
    dl->AddLine(ImVec2(x, top), ImVec2(x, bottom), color::grid);
    if (!xa.tick_labels) continue;
    const ImVec2 ts = ImGui::CalcTextSize(t.label.c_str());
    dl->AddText(ImVec2(x - ts.x * 0.5f, bottom + fh * 0.2f), color::text, t.label.c_str());
  }
  if (!yticks.factor.empty())
    dl->AddText(ImVec2(left + 3, top + 2), color::muted, yticks.factor.c_str());
  if (!xticks.factor.empty() && xa.tick_labels)
    dl->AddText(ImVec2(right - ImGui::CalcTextSize(xticks.factor.c_str()).x, bottom + fh * 1.3f),
                color::muted, xticks.factor.c_str());

  // Data, clipped to the plot area.
  const std::vector<ImU32> colors = series_colors(plot);
  const ImVec2 clip_min(left, top), clip_max(right + 1, bottom + 1);
  dl->PushClipRect(clip_min, clip_max, true);
  for (const Band& band : plot.bands())
    dl->AddRectFilled(ImVec2(sx(band.x0), top), ImVec2(sx(band.x1), bottom),
                      color_or(band.color, color::boundary, plot_style::band_opacity));
  const auto& verticals = plot.vertical_lines();
  for (int i = 0; i < static_cast<int>(verticals.size()); ++i) {
    const ReferenceLine& line = verticals[i];
    const float x = static_cast<float>(sx(line.value));
    const ImU32 c = color_or(line.color, color::boundary);
    if (line.handle < 0) {
      dl->AddLine(ImVec2(x, top), ImVec2(x, bottom), c, 1.0f);
      continue;
    }
    const float width = (i == near_line || i == dragging) ? 3.0f : 1.0f;
    for (float y = top; y < bottom; y += 8.0f)
      dl->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 5.0f, bottom)), c, width);
    dl->AddTriangleFilled(ImVec2(x - 4, top), ImVec2(x + 4, top), ImVec2(x, top + 6), c);
  }
  for (const ReferenceLine& level : plot.horizontal_lines()) {
    const float y = static_cast<float>(sy(level.value));
    if (!std::isfinite(y)) continue;
    const ImU32 c = color_or(level.color, color::muted);
    for (float x = left; x < right; x += 10.0f)  // dashed
      dl->AddLine(ImVec2(x, y), ImVec2(std::min(x + 6.0f, right), y), c, 1.0f);
    if (!level.label.empty())
      dl->AddText(ImVec2(right - ImGui::CalcTextSize(level.label.c_str()).x - 4,
                         y - fh - 1 < top ? y + 2 : y - fh - 1),
                  c, level.label.c_str());
  }
  for (std::size_t k = 0; k < plot.series().size(); ++k)
    draw_series(dl, plot.series()[k], colors[k], sx, sy, clip_min, clip_max);
  for (const Highlight& h : plot.highlights()) {
    const ImVec2 c(sx(h.x), sy(h.y));
    if (std::isfinite(c.x) && std::isfinite(c.y))
      dl->AddCircle(c, fh * 0.45f, color_or(h.color, color::error), 12, 2.0f);
  }
  for (const Annotation& a : plot.annotations()) {
    const ImVec2 c(sx(a.x), sy(a.y));
    if (!std::isfinite(c.x) || !std::isfinite(c.y)) continue;
    dl->AddCircleFilled(c, fh * 0.15f, color::text, 8);
    const bool above = c.y - fh * 1.1f >= top;  // below the point when the top is too near
    dl->AddText(ImVec2(c.x + fh * 0.3f, above ? c.y - fh * 1.1f : c.y + fh * 0.2f), color::text,
                a.text.c_str());
  }
  dl->PopClipRect();
  dl->AddRect(ImVec2(left, top), ImVec2(right, bottom), color::frame);
  draw_legend(dl, plot, colors, ImVec2(right, top), fh);

  // Title and axis labels.
  dl->AddText(ImVec2(origin.x, origin.y + fh * 0.15f), color::text, plot.y_label.c_str());
  if (!plot.title.empty()) {
    const ImVec2 ts = ImGui::CalcTextSize(plot.title.c_str());
    dl->AddText(ImVec2(std::max(left + (right - left - ts.x) * 0.5f,
                                origin.x + ImGui::CalcTextSize(plot.y_label.c_str()).x + fh),
                       origin.y + fh * 0.15f),
                color::text, plot.title.c_str());
  }
  if (xa.tick_labels && !x_label.empty()) {
    const ImVec2 ts = ImGui::CalcTextSize(x_label.c_str());
    dl->AddText(ImVec2(left + (right - left - ts.x) * 0.5f, bottom + fh * 1.35f), color::text,
                x_label.c_str());
  }

  // Crosshair and read-out.
  const bool in_plot =
      hovered && mouse.x >= left && mouse.x <= right && mouse.y >= top && mouse.y <= bottom;
  std::optional<double> cross;
  if (in_plot) {
    cross = to_data(sx, mouse.x);
    if (crosshair) crosshair->x = cross;
  } else if (crosshair) {
    cross = crosshair->x ? crosshair->x : crosshair->last;
  }
  if (!cross) return events;
  const float cx = static_cast<float>(sx(*cross));
  dl->AddLine(ImVec2(cx, top), ImVec2(cx, bottom), IM_COL32(60, 60, 60, 120));
  for (std::size_t k = 0; k < plot.series().size(); ++k)
    if (const auto i = nearest(plot.series()[k], *cross)) {
      const Series& s = plot.series()[k];
      const ImVec2 c(sx(s.x[*i]), sy(s.y[*i]));
      if (std::isfinite(c.x) && std::isfinite(c.y) && c.y >= top && c.y <= bottom)
        dl->AddCircleFilled(c, fh * 0.22f, colors[k]);
    }
  if (!in_plot) return events;
  ImGui::BeginTooltip();
  ImGui::Text("%s = %s", x_label.c_str(), number_text(*cross).c_str());
  for (std::size_t k = 0; k < plot.series().size(); ++k)
    if (const auto i = nearest(plot.series()[k], *cross)) {
      const Series& s = plot.series()[k];
      ImGui::ColorButton("##swatch", ImGui::ColorConvertU32ToFloat4(colors[k]),
                         ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                         ImVec2(fh * 0.7f, fh * 0.7f));
      ImGui::SameLine();
      ImGui::Text("%s: %s", (s.label.empty() ? plot.y_label : s.label).c_str(),
                  number_text(s.y[*i]).c_str());
    }
  for (const ReferenceLine& line : verticals)
    if (!line.label.empty() && std::abs(sx(line.value) - mouse.x) < fh * 0.4f)
      ImGui::TextUnformatted(line.label.c_str());
  for (const Highlight& h : plot.highlights())
    if (std::abs(sx(h.x) - mouse.x) < fh * 0.6f && std::abs(sy(h.y) - mouse.y) < fh * 0.6f) {
      ImGui::PushStyleColor(ImGuiCol_Text, color_or(h.color, color::error));
      ImGui::PushTextWrapPos(fh * 28.0f);
      ImGui::TextUnformatted(h.text.c_str());
      ImGui::PopTextWrapPos();
      ImGui::PopStyleColor();
    }
  ImGui::TextDisabled(near_line >= 0 ? "drag: move the line"
                                     : "wheel: zoom, drag: pan, double-click: fit");
  ImGui::EndTooltip();
  return events;
}

}  // namespace

PlotEvents draw_plot(const char* id, const Plot& plot, AxisView& x_view, AxisView& y_view,
                     ImVec2 size, bool x_tick_labels, Crosshair* crosshair) {
  XAxis xa{plot.log_x, plot.x_range, &plot.x_label, x_tick_labels, plot.x_tick_step};
  if (!xa.extent) {
    Extent e;
    add_x_data(e, plot, plot.log_x);
    xa.extent = fit_x(e, plot.log_x);
  }
  return draw_panel(id, plot, xa, x_view, y_view, size, crosshair);
}

PlotEvents draw_figure(const char* id, const Figure& figure, FigureView& view, ImVec2 size) {
  PlotEvents first;
  const auto& panels = figure.panels();
  if (panels.empty()) return first;
  const std::size_t n = panels.size();
  view.y.resize(n);
  view.x.resize(figure.shared_x ? 1 : n);
  view.crosshair.next_frame();
  ImGui::PushID(id);
  if (!figure.title.empty()) {
    ImGui::TextUnformatted(figure.title.c_str());
    size.y -= ImGui::GetTextLineHeightWithSpacing();
  }
  const float spacing = ImGui::GetStyle().ItemSpacing.y;
  const float height = std::max(60.0f, size.y / static_cast<float>(n) - spacing);
  XAxis shared;
  if (figure.shared_x) {  // the first panel's x settings; the range covers every panel's data
    const Plot& lead = panels.front();
    shared = {lead.log_x, lead.x_range, &lead.x_label, false, lead.x_tick_step};
    if (!shared.extent) {
      Extent e;
      for (const Plot& p : panels) add_x_data(e, p, lead.log_x);
      shared.extent = fit_x(e, lead.log_x);
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    ImGui::PushID(static_cast<int>(k));
    PlotEvents events;
    if (figure.shared_x) {
      XAxis xa = shared;
      xa.tick_labels = k + 1 == n;
      events = draw_panel("panel", panels[k], xa, view.x[0], view.y[k], ImVec2(size.x, height),
                          &view.crosshair);
    } else {
      events = draw_plot("panel", panels[k], view.x[k], view.y[k], ImVec2(size.x, height));
    }
    if (first.dragged_handle < 0) first = events;
    ImGui::PopID();
  }
  ImGui::PopID();
  return first;
}

}  // namespace polarform::studio
