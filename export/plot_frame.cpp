#include "export/plot_frame.h"

#include "export/plot_style.h"

namespace polarform {

namespace {

namespace style = plot_style;

void draw_text(SvgWriter& svg, double x, double y, std::string_view text, std::string_view anchor,
               double size, std::string_view cls) {
  svg.begin("text")
      .attr("class", cls)
      .attr("x", x)
      .attr("y", y)
      .attr("text-anchor", anchor)
      .attr("font-size", size)
      .attr("fill", style::text_color)
      .text(text);
}

// Frame, tick marks and tick labels, in crisp 1-px lines.
void draw_axes(SvgWriter& svg, const PanelFrame& f) {
  const PixelRect& a = f.area;
  std::string ticks;
  auto x_tick = [&](double v, double length) {
    const double x = f.x(v);
    if (x >= a.left - 0.5 && x <= a.right + 0.5)
      ticks += "M" + svg_number(x) + " " + svg_number(a.bottom) + "v" + svg_number(length);
  };
  auto y_tick = [&](double v, double length) {
    const double y = f.y(v);
    if (y >= a.top - 0.5 && y <= a.bottom + 0.5)
      ticks += "M" + svg_number(a.left) + " " + svg_number(y) + "h" + svg_number(-length);
  };
  for (const Tick& t : f.x_ticks.major) x_tick(t.value, style::tick_length);
  for (const double v : f.x_ticks.minor) x_tick(v, style::minor_tick_length);
  for (const Tick& t : f.y_ticks.major) y_tick(t.value, style::tick_length);
  for (const double v : f.y_ticks.minor) y_tick(v, style::minor_tick_length);

  svg.begin("g").attr("stroke", style::frame_color).attr("shape-rendering", "crispEdges").open();
  svg.begin("path").attr("class", "ticks").attr("d", ticks).empty();
  svg.begin("rect")
      .attr("class", "plot-area")
      .attr("x", a.left)
      .attr("y", a.top)
      .attr("width", a.right - a.left)
      .attr("height", a.bottom - a.top)
      .attr("fill", "none")
      .empty();
  svg.close();

  if (f.x_tick_labels)
    for (const Tick& t : f.x_ticks.major)
      draw_text(svg, f.x(t.value), a.bottom + style::tick_length + 3 + style::tick_font, t.label,
                "middle", style::tick_font, "x-tick");
  for (const Tick& t : f.y_ticks.major)
    svg.begin("text")
        .attr("class", "y-tick")
        .attr("x", a.left - style::tick_length - 4)
        .attr("y", f.y(t.value))
        .attr("dy", "0.35em")
        .attr("text-anchor", "end")
        .attr("font-size", style::tick_font)
        .attr("fill", style::text_color)
        .text(t.label);
}

void draw_labels(SvgWriter& svg, const Plot& plot, const PanelFrame& f) {
  const PixelRect& a = f.area;
  const double label_baseline = a.bottom + style::tick_length + 3 + style::tick_font + 19;
  if (!plot.title.empty())
    svg.begin("text")
        .attr("class", "title")
        .attr("x", 0.5 * (a.left + a.right))
        .attr("y", a.top - 9)
        .attr("text-anchor", "middle")
        .attr("font-size", style::title_font)
        .attr("font-weight", "600")
        .attr("fill", style::text_color)
        .text(plot.title);
  if (!f.x_label.empty())
    draw_text(svg, 0.5 * (a.left + a.right), label_baseline, f.x_label, "middle", style::label_font,
              "x-label");
  if (!plot.y_label.empty()) {
    const double x = kFigurePadding + 0.8 * style::label_font, y = 0.5 * (a.top + a.bottom);
    svg.begin("text")
        .attr("class", "y-label")
        .attr("x", x)
        .attr("y", y)
        .attr("text-anchor", "middle")
        .attr("transform", "rotate(-90 " + svg_number(x) + " " + svg_number(y) + ")")
        .attr("font-size", style::label_font)
        .attr("fill", style::text_color)
        .text(plot.y_label);
  }
  if (!f.y_ticks.factor.empty())
    draw_text(svg, a.left, a.top - 4, f.y_ticks.factor, "start", style::note_font, "y-factor");
  if (!f.x_ticks.factor.empty() && f.x_tick_labels)
    draw_text(svg, a.right, label_baseline, f.x_ticks.factor, "end", style::note_font, "x-factor");
}

}  // namespace

// Skips lines on the frame's edges.
void draw_grid(SvgWriter& svg, const PanelFrame& f) {
  const PixelRect& a = f.area;
  std::string major, minor;
  auto vertical = [&](std::string& d, double x) {
    if (x > a.left + 0.5 && x < a.right - 0.5)
      d += "M" + svg_number(x) + " " + svg_number(a.top) + "V" + svg_number(a.bottom);
  };
  auto horizontal = [&](std::string& d, double y) {
    if (y > a.top + 0.5 && y < a.bottom - 0.5)
      d += "M" + svg_number(a.left) + " " + svg_number(y) + "H" + svg_number(a.right);
  };
  for (const Tick& t : f.x_ticks.major) vertical(major, f.x(t.value));
  for (const Tick& t : f.y_ticks.major) horizontal(major, f.y(t.value));
  if (f.x.log())
    for (const double v : f.x_ticks.minor) vertical(minor, f.x(v));
  if (f.y.log())
    for (const double v : f.y_ticks.minor) horizontal(minor, f.y(v));
  if (!minor.empty())
    svg.begin("path")
        .attr("class", "grid minor")
        .attr("d", minor)
        .attr("stroke", style::minor_grid_color)
        .attr("shape-rendering", "crispEdges")
        .empty();
  if (!major.empty())
    svg.begin("path")
        .attr("class", "grid")
        .attr("d", major)
        .attr("stroke", style::grid_color)
        .attr("shape-rendering", "crispEdges")
        .empty();
}

void draw_frame(SvgWriter& svg, const Plot& plot, const PanelFrame& frame) {
  draw_axes(svg, frame);
  draw_labels(svg, plot, frame);
}

}  // namespace polarform
