#include "ui/studio/plot_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "export/plot_axis.h"
#include "export/polyline_path.h"
#include "ui/studio/colors.h"
#include "ui/studio/opaque_fill.h"
#include "ui/studio/polyline_simplify.h"

namespace polarform::studio {
namespace {

constexpr double kTickFont = 12.0;  // export/plot_style's tick font, which choose_ticks assumes

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

AxisRange fit_x(const PlotSpec& spec) {
  if (spec.x_extent) return *spec.x_extent;
  Extent e;
  for (const PlotLine& line : spec.lines)
    for (double x : line.x) e.add(x, spec.log_x);
  if (e.empty()) return spec.log_x ? AxisRange{0.1, 10.0} : AxisRange{0.0, 1.0};
  return e.hi > e.lo ? AxisRange{e.lo, e.hi} : padded({e.lo, e.hi}, spec.log_x, 0.05);
}

AxisRange fit_y(const PlotSpec& spec, const AxisRange& x) {
  if (spec.y_extent) return *spec.y_extent;
  Extent e;
  for (const PlotLine& line : spec.lines) {
    const std::size_t n = std::min(line.x.size(), line.y.size());
    for (std::size_t i = 0; i < n; ++i)
      if (line.x[i] >= x.min && line.x[i] <= x.max) e.add(line.y[i], spec.log_y);
  }
  for (const PlotLevel& level : spec.levels) e.add(level.y, spec.log_y);
  for (const PlotPoint& p : spec.points)
    if (p.x >= x.min && p.x <= x.max) e.add(p.y, spec.log_y);
  if (e.empty()) return spec.log_y ? AxisRange{0.1, 10.0} : AxisRange{0.0, 1.0};
  return padded({e.lo, e.hi}, spec.log_y, 0.05);
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
// by the ratio of the fonts, so spacing decisions carry over to ImGui's font size.
TickSet ticks_for(const AxisRange& range, bool log, double length, AxisSide side) {
  const double font = ImGui::GetFontSize();
  const AxisScale layout(range, log, 0.0, length * kTickFont / font);
  return choose_ticks(layout, side, std::nullopt, "ticks");
}

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

// Index of the sample of `line` nearest to x (lines are sorted by x).
std::optional<std::size_t> nearest(const PlotLine& line, double x) {
  const std::size_t n = std::min(line.x.size(), line.y.size());
  if (n == 0) return std::nullopt;
  const auto it =
      std::lower_bound(line.x.begin(), line.x.begin() + static_cast<std::ptrdiff_t>(n), x);
  std::size_t i = static_cast<std::size_t>(it - line.x.begin());
  if (i == n) return n - 1;
  if (i > 0 && std::abs(line.x[i - 1] - x) < std::abs(line.x[i] - x)) --i;
  return i;
}

void draw_line(ImDrawList* dl, const PlotLine& line, const AxisScale& sx, const AxisScale& sy) {
  const std::size_t n = std::min(line.x.size(), line.y.size());
  if (n == 0) return;
  // Only the samples inside the visible x range, plus one on each side.
  const auto first = std::lower_bound(
      line.x.begin(), line.x.begin() + static_cast<std::ptrdiff_t>(n), sx.range().min);
  const auto last =
      std::upper_bound(first, line.x.begin() + static_cast<std::ptrdiff_t>(n), sx.range().max);
  const std::size_t i0 =
      static_cast<std::size_t>(std::max<std::ptrdiff_t>(first - line.x.begin() - 1, 0));
  const std::size_t i1 = std::min(n, static_cast<std::size_t>(last - line.x.begin()) + 1);
  std::vector<PixelPoint> pixels;
  pixels.reserve(i1 - i0);
  for (std::size_t i = i0; i < i1; ++i) pixels.push_back({sx(line.x[i]), sy(line.y[i])});
  std::vector<ImVec2> points;
  for (const Polyline& run : finite_runs(pixels)) {
    const Polyline thin = simplify_polyline(decimate_to_columns(run));
    points.clear();
    for (const PixelPoint& p : thin)
      points.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
    if (points.size() == 1) points.push_back(points.front());
    dl->AddPolyline(points.data(), static_cast<int>(points.size()), line.color, 0, line.thickness);
  }
}

// The draggable marker within `reach` pixels of the mouse inside the plot's height, or -1.
int nearest_draggable(const PlotSpec& spec, const AxisScale& sx, ImVec2 mouse, float reach,
                      float top, float bottom) {
  if (!ImGui::IsItemHovered() || mouse.y < top || mouse.y > bottom) return -1;
  int best = -1;
  double best_distance = reach;
  for (int i = 0; i < static_cast<int>(spec.markers.size()); ++i) {
    if (!spec.markers[i].draggable) continue;
    const double d = std::abs(sx(spec.markers[i].x) - mouse.x);
    if (d <= best_distance) {
      best = i;
      best_distance = d;
    }
  }
  return best;
}

// A legend in the plot's top-right corner when two or more lines carry labels: a swatch of each
// line's colour and its label, on a light box.
void draw_legend(ImDrawList* dl, const std::vector<PlotLine>& lines, ImVec2 top_right, float fh) {
  std::vector<const PlotLine*> labelled;
  float width = 0.0f;
  for (const PlotLine& line : lines)
    if (!line.label.empty()) {
      labelled.push_back(&line);
      width = std::max(width, ImGui::CalcTextSize(line.label.c_str()).x);
    }
  if (labelled.size() < 2) return;
  const float swatch = fh * 1.5f, pad = fh * 0.3f;
  const ImVec2 min(top_right.x - width - swatch - 3 * pad, top_right.y + pad);
  const ImVec2 max(top_right.x - pad, min.y + labelled.size() * fh + 2 * pad);
  dl->AddRectFilled(min, max, IM_COL32(255, 255, 255, 215));
  dl->AddRect(min, max, color::frame);
  for (std::size_t k = 0; k < labelled.size(); ++k) {
    const float y = min.y + pad + k * fh;
    dl->AddLine(ImVec2(min.x + pad, y + fh * 0.5f), ImVec2(min.x + pad + swatch, y + fh * 0.5f),
                labelled[k]->color, labelled[k]->thickness);
    dl->AddText(ImVec2(min.x + 2 * pad + swatch, y), color::text, labelled[k]->label.c_str());
  }
}

}  // namespace

PlotEvents draw_plot(const PlotSpec& spec, AxisView& x_view, AxisView& y_view, ImVec2 size,
                     Crosshair* crosshair) {
  PlotEvents events;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  size.x = std::max(size.x, 120.0f);
  size.y = std::max(size.y, 80.0f);
  const ImGuiID drag_key = ImGui::GetID(spec.id);
  ImGui::InvisibleButton(spec.id, size);
  const bool hovered = ImGui::IsItemHovered();
  const bool active = ImGui::IsItemActive();
  const bool activated = ImGui::IsItemActivated();
  const ImGuiIO& io = ImGui::GetIO();
  const float fh = ImGui::GetFontSize();

  if (x_view.range && !usable(*x_view.range, spec.log_x)) x_view.range.reset();
  if (y_view.range && !usable(*y_view.range, spec.log_y)) y_view.range.reset();
  const AxisRange xr = x_view.range ? *x_view.range : fit_x(spec);
  const AxisRange yr = y_view.range ? *y_view.range : fit_y(spec, xr);

  // Layout: title line on top (title, y label), tick labels and x label below, y ticks left.
  const float top = origin.y + fh * 1.5f;
  const float bottom = origin.y + size.y -
                       (spec.x_tick_labels ? fh * (spec.x_label.empty() ? 1.5f : 2.7f) : fh * 0.5f);
  const TickSet yticks = ticks_for(yr, spec.log_y, std::max(10.0f, bottom - top), AxisSide::left);
  float label_width = 0.0f;
  for (const Tick& t : yticks.major)
    label_width = std::max(label_width, ImGui::CalcTextSize(t.label.c_str()).x);
  const float left = origin.x + label_width + fh * 0.8f;
  const float right = origin.x + size.x - fh * 0.8f;
  if (right - left < 20.0f || bottom - top < 20.0f) return events;
  const AxisScale sx(xr, spec.log_x, left, right);
  const AxisScale sy(yr, spec.log_y, bottom, top);
  const TickSet xticks = ticks_for(xr, spec.log_x, right - left, AxisSide::bottom);

  // Input: a draggable marker under the mouse follows it; otherwise zoom about the cursor (over an
  // axis: that axis only), drag to pan, double-click to fit.
  const ImVec2 mouse = io.MousePos;
  ImGuiStorage* storage = ImGui::GetStateStorage();
  const int near_marker = nearest_draggable(spec, sx, mouse, fh * 0.4f, top, bottom);
  if (activated) storage->SetInt(drag_key, near_marker);
  const int dragging = active ? storage->GetInt(drag_key, -1) : -1;
  if (!active) storage->SetInt(drag_key, -1);
  if (dragging >= 0 && dragging < static_cast<int>(spec.markers.size())) {
    events.dragged_marker = dragging;
    events.marker_x = std::clamp(to_data(sx, mouse.x), xr.min, xr.max);
  }
  if (near_marker >= 0 || dragging >= 0) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  if (hovered && io.MouseWheel != 0.0f) {
    const double factor = std::pow(0.85, io.MouseWheel);
    const bool over_y_axis = mouse.x<left, over_x_axis = mouse.y> bottom;
    if (!over_y_axis) x_view.range = zoomed(xr, spec.log_x, to_data(sx, mouse.x), factor);
    if (!over_x_axis) y_view.range = zoomed(yr, spec.log_y, to_data(sy, mouse.y), factor);
  }
  if (dragging < 0 && active && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 1.0f)) {
    if (io.MouseDelta.x != 0.0f)
      x_view.range = panned(xr, spec.log_x, io.MouseDelta.x, right - left);
    if (io.MouseDelta.y != 0.0f)
      y_view.range = panned(yr, spec.log_y, -io.MouseDelta.y, bottom - top);
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
    if (!spec.x_tick_labels) continue;
    const ImVec2 ts = ImGui::CalcTextSize(t.label.c_str());
    dl->AddText(ImVec2(x - ts.x * 0.5f, bottom + fh * 0.2f), color::text, t.label.c_str());
  }
  if (!yticks.factor.empty())
    dl->AddText(ImVec2(left + 3, top + 2), color::muted, yticks.factor.c_str());
  if (!xticks.factor.empty() && spec.x_tick_labels)
    dl->AddText(ImVec2(right - ImGui::CalcTextSize(xticks.factor.c_str()).x, bottom + fh * 1.3f),
                color::muted, xticks.factor.c_str());

  // Data, clipped to the plot area.
  dl->PushClipRect(ImVec2(left, top), ImVec2(right + 1, bottom + 1), true);
  for (const PlotBand& band : spec.bands)
    dl->AddRectFilled(ImVec2(sx(band.x0), top), ImVec2(sx(band.x1), bottom), band.color);
  for (int i = 0; i < static_cast<int>(spec.markers.size()); ++i) {
    const PlotMarker& m = spec.markers[i];
    const float x = static_cast<float>(sx(m.x));
    const ImU32 c = m.color ? m.color : color::boundary;
    if (!m.draggable) {
      dl->AddLine(ImVec2(x, top), ImVec2(x, bottom), c, 1.0f);
      continue;
    }
    const float width = (i == near_marker || i == dragging) ? 3.0f : 1.0f;
    for (float y = top; y < bottom; y += 8.0f)
      dl->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 5.0f, bottom)), c, width);
    dl->AddTriangleFilled(ImVec2(x - 4, top), ImVec2(x + 4, top), ImVec2(x, top + 6), c);
  }
  for (const PlotLevel& level : spec.levels) {
    const float y = static_cast<float>(sy(level.y));
    if (!std::isfinite(y)) continue;
    for (float x = left; x < right; x += 10.0f)  // dashed
      dl->AddLine(ImVec2(x, y), ImVec2(std::min(x + 6.0f, right), y),
                  level.color ? level.color : color::muted, 1.0f);
    if (!level.label.empty())
      dl->AddText(ImVec2(right - ImGui::CalcTextSize(level.label.c_str()).x - 4,
                         y - fh - 1 < top ? y + 2 : y - fh - 1),
                  level.color ? level.color : color::muted, level.label.c_str());
  }
  for (const PlotLine& line : spec.lines) draw_line(dl, line, sx, sy);
  for (const PlotPoint& p : spec.points) {
    const ImVec2 c(sx(p.x), sy(p.y));
    if (!std::isfinite(c.x) || !std::isfinite(c.y)) continue;
    if (p.small)
      dl->AddCircleFilled(c, fh * 0.2f, p.color ? p.color : color::error, 8);
    else
      dl->AddCircle(c, fh * 0.45f, p.color ? p.color : color::error, 12, 2.0f);
  }
  dl->PopClipRect();
  dl->AddRect(ImVec2(left, top), ImVec2(right, bottom), color::frame);
  draw_legend(dl, spec.lines, ImVec2(right, top), fh);

  // Title and axis labels.
  dl->AddText(ImVec2(origin.x, origin.y + fh * 0.15f), color::text, spec.y_label.c_str());
  if (!spec.title.empty()) {
    const ImVec2 ts = ImGui::CalcTextSize(spec.title.c_str());
    dl->AddText(ImVec2(std::max(left + (right - left - ts.x) * 0.5f,
                                origin.x + ImGui::CalcTextSize(spec.y_label.c_str()).x + fh),
                       origin.y + fh * 0.15f),
                color::text, spec.title.c_str());
  }
  if (spec.x_tick_labels && !spec.x_label.empty()) {
    const ImVec2 ts = ImGui::CalcTextSize(spec.x_label.c_str());
    dl->AddText(ImVec2(left + (right - left - ts.x) * 0.5f, bottom + fh * 1.35f), color::text,
                spec.x_label.c_str());
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
  for (const PlotLine& line : spec.lines)
    if (const auto i = nearest(line, *cross)) {
      const ImVec2 c(sx(line.x[*i]), sy(line.y[*i]));
      if (std::isfinite(c.x) && std::isfinite(c.y) && c.y >= top && c.y <= bottom)
        dl->AddCircleFilled(c, fh * 0.22f, line.color);
    }
  if (!in_plot) return events;
  ImGui::BeginTooltip();
  ImGui::Text("%s = %s", spec.x_label.c_str(), number(*cross).c_str());
  for (const PlotLine& line : spec.lines)
    if (const auto i = nearest(line, *cross)) {
      ImGui::ColorButton("##swatch", ImGui::ColorConvertU32ToFloat4(line.color),
                         ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                         ImVec2(fh * 0.7f, fh * 0.7f));
      ImGui::SameLine();
      ImGui::Text("%s: %s", line.label.c_str(), number(line.y[*i]).c_str());
    }
  for (const PlotMarker& m : spec.markers)
    if (!m.label.empty() && std::abs(sx(m.x) - mouse.x) < fh * 0.4f)
      ImGui::TextUnformatted(m.label.c_str());
  for (const PlotPoint& p : spec.points)
    if (!p.text.empty() && std::abs(sx(p.x) - mouse.x) < fh * 0.6f &&
        std::abs(sy(p.y) - mouse.y) < fh * 0.6f) {
      ImGui::PushStyleColor(ImGuiCol_Text, p.color ? p.color : color::error);
      ImGui::PushTextWrapPos(fh * 28.0f);
      ImGui::TextUnformatted(p.text.c_str());
      ImGui::PopTextWrapPos();
      ImGui::PopStyleColor();
    }
  ImGui::TextDisabled(near_marker >= 0 ? "drag: move the boundary"
                                       : "wheel: zoom, drag: pan, double-click: fit");
  ImGui::EndTooltip();
  return events;
}

}  // namespace polarform::studio
