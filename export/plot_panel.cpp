#include "export/plot_panel.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "export/plot_frame.h"
#include "export/plot_legend.h"
#include "export/plot_marks.h"
#include "export/plot_style.h"
#include "export/text_width.h"

namespace polarform {

namespace {

namespace style = plot_style;

constexpr double kDenseRunPointsPerColumn = 4;  // M4 keeps at most 4 per pixel column

// A series mapped to pixels, ready to draw.
struct DrawnSeries {
  const Series* series;
  std::string color;
  MarkerShape shape;
  int omitted = 0;             // finite points dropped because they are <= 0 on a log axis
  std::vector<Polyline> runs;  // decimated, not yet clipped
  Polyline markers;            // inside the plot area, one per pixel
};

bool draws_line(Series::Style s) { return s != Series::Style::markers; }
bool draws_markers(Series::Style s) {
  return s == Series::Style::markers || s == Series::Style::line_markers;
}

std::string or_default(const std::string& color, std::string_view fallback) {
  return color.empty() ? std::string(fallback) : color;
}

std::vector<DrawnSeries> map_series(const Plot& plot, const PanelFrame& f) {
  std::vector<DrawnSeries> drawn;
  std::size_t palette_index = 0;
  int marker_index = 0;
  for (const Series& s : plot.series()) {
    DrawnSeries d{&s, s.color, marker_shape(marker_index), 0, {}, {}};
    if (d.color.empty()) d.color = style::palette[palette_index++ % style::palette.size()];
    if (draws_markers(s.style)) ++marker_index;
    Polyline pixels(s.x.size());
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      pixels[i] = {f.x(s.x[i]), f.y(s.y[i])};
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]) &&
          ((f.x.log() && s.x[i] <= 0) || (f.y.log() && s.y[i] <= 0)))
        ++d.omitted;
    }
    // Decimate only runs too dense to show anyway, so that zooming into the SVG keeps detail.
    const double dense = kDenseRunPointsPerColumn * (f.area.right - f.area.left);
    for (Polyline& run : finite_runs(pixels))
      d.runs.push_back(static_cast<double>(run.size()) > dense ? decimate_to_columns(run)
                                                               : std::move(run));
    if (draws_markers(s.style)) {
      std::set<std::pair<long long, long long>> occupied;
      for (const Polyline& run : d.runs)
        for (const PixelPoint& p : run)
          if (f.area.contains(p) && occupied.insert({std::llround(p.x), std::llround(p.y)}).second)
            d.markers.push_back(p);
    }
    drawn.push_back(std::move(d));
  }
  return drawn;
}

std::string legend_label(const DrawnSeries& d) {
  if (d.omitted == 0) return d.series->label;
  return d.series->label + " (" + std::to_string(d.omitted) + " point" +
         (d.omitted == 1 ? "" : "s") + " \u2264 0 omitted)";
}

// The box of a line of text whose baseline starts at (x, y) (anchor start) or ends there.
PixelRect text_box(double x, double y, const std::string& text, double font, bool anchor_end) {
  const double w = text_width(text, font);
  const double left = anchor_end ? x - w : x;
  return {left, y - font, left + w, y + 0.25 * font};
}

// A vertical reference line's label: rotated to run up along the line, ending near the top, on
// the line's left; its anchor point and its box.
struct VerticalLabel {
  double x, y;
  PixelRect box;
};
VerticalLabel vertical_label(double line_x, const PixelRect& a, const std::string& text) {
  const double x = line_x - 4, y = a.top + 4, font = style::note_font;
  return {x, y, {x - font, y, x + 0.25 * font, y + text_width(text, font)}};
}

// A horizontal reference line's label: above the line, ending near the right edge.
PixelRect horizontal_label_box(double line_y, const PixelRect& a, const std::string& text) {
  return text_box(a.right - 4, line_y - 4, text, style::note_font, true);
}

// An annotation's text: right of and above its point where it fits, else left of or below it.
struct AnnotationText {
  double x, y;
  bool anchor_end;
  PixelRect box;
};
AnnotationText annotation_text(PixelPoint p, const std::string& text, const PixelRect& a) {
  const bool fits_right = p.x + 6 + text_width(text, style::note_font) <= a.right;
  const bool fits_above = p.y - 6 - style::note_font >= a.top;
  const double x = fits_right ? p.x + 6 : p.x - 6;
  const double y = fits_above ? p.y - 6 : p.y + 6 + style::note_font;
  return {x, y, !fits_right, text_box(x, y, text, style::note_font, !fits_right)};
}

PixelRect square_around(PixelPoint p, double half) {
  return {p.x - half, p.y - half, p.x + half, p.y + half};
}

// A white outline painted under the glyphs, for notes drawn over data.
SvgWriter& with_halo(SvgWriter& svg) {
  return svg.attr("stroke", "white")
      .attr("stroke-width", style::halo_width)
      .attr("stroke-linejoin", "round")
      .attr("paint-order", "stroke");
}

void draw_bands(SvgWriter& svg, const Plot& plot, const PanelFrame& f) {
  const PixelRect& a = f.area;
  for (const Band& band : plot.bands()) {
    // An edge at or below zero on a log axis lies beyond the left end.
    const double x0 = std::isnan(f.x(band.x0)) ? a.left : std::clamp(f.x(band.x0), a.left, a.right);
    const double x1 = std::isnan(f.x(band.x1)) ? a.left : std::clamp(f.x(band.x1), a.left, a.right);
    if (x1 <= x0) continue;
    svg.begin("rect")
        .attr("class", "band")
        .attr("x", x0)
        .attr("y", a.top)
        .attr("width", x1 - x0)
        .attr("height", a.bottom - a.top)
        .attr("fill", or_default(band.color, style::band_color))
        .attr("fill-opacity", style::band_opacity)
        .empty();
  }
}

void draw_reference_lines(SvgWriter& svg, const Plot& plot, const PanelFrame& f) {
  const PixelRect& a = f.area;
  for (const ReferenceLine& line : plot.vertical_lines()) {
    const double x = f.x(line.value);
    if (!(x >= a.left && x <= a.right)) continue;
    const std::string color = or_default(line.color, style::reference_color);
    svg.begin("path")
        .attr("class", "reference vertical")
        .attr("d", "M" + svg_number(x) + " " + svg_number(a.top) + "V" + svg_number(a.bottom))
        .attr("stroke", color)
        .attr("stroke-width", style::reference_width)
        .attr("stroke-dasharray", style::reference_dash)
        .empty();
    if (line.label.empty()) continue;
    const VerticalLabel label = vertical_label(x, a, line.label);
    svg.begin("text")
        .attr("class", "reference-label")
        .attr("x", label.x)
        .attr("y", label.y)
        .attr("text-anchor", "end")
        .attr("transform", "rotate(-90 " + svg_number(label.x) + " " + svg_number(label.y) + ")")
        .attr("font-size", style::note_font)
        .attr("fill", color);
    with_halo(svg).text(line.label);
  }
  for (const ReferenceLine& line : plot.horizontal_lines()) {
    const double y = f.y(line.value);
    if (!(y >= a.top && y <= a.bottom)) continue;
    const std::string color = or_default(line.color, style::reference_color);
    svg.begin("path")
        .attr("class", "reference horizontal")
        .attr("d", "M" + svg_number(a.left) + " " + svg_number(y) + "H" + svg_number(a.right))
        .attr("stroke", color)
        .attr("stroke-width", style::reference_width)
        .attr("stroke-dasharray", style::reference_dash)
        .empty();
    if (line.label.empty()) continue;
    svg.begin("text")
        .attr("class", "reference-label")
        .attr("x", a.right - 4)
        .attr("y", y - 4)
        .attr("text-anchor", "end")
        .attr("font-size", style::note_font)
        .attr("fill", color);
    with_halo(svg).text(line.label);
  }
}

void draw_series(SvgWriter& svg, const std::vector<DrawnSeries>& drawn, const PixelRect& area) {
  for (const DrawnSeries& d : drawn) {
    if (draws_line(d.series->style)) {
      std::vector<Polyline> pieces;
      for (const Polyline& run : d.runs)
        for (Polyline& piece : clip_polyline(run, area)) pieces.push_back(std::move(piece));
      if (!pieces.empty()) {
        svg.begin("path")
            .attr("class", "series")
            .attr("d", path_data(pieces))
            .attr("fill", "none")
            .attr("stroke", d.color)
            .attr("stroke-width", style::line_width)
            .attr("stroke-linejoin", "round")
            .attr("stroke-linecap", "round");
        if (d.series->style == Series::Style::dashed) svg.attr("stroke-dasharray", style::dash);
        svg.empty();
      }
    }
    if (!d.markers.empty()) {
      std::string path;
      for (const PixelPoint& p : d.markers) path += marker_path(d.shape, p, style::marker_radius);
      svg.begin("path")
          .attr("class", "markers")
          .attr("d", path)
          .attr("fill", d.color)
          .attr("stroke", "white")
          .attr("stroke-width", 0.75)
          .empty();
    }
  }
}

void draw_annotations(SvgWriter& svg, const Plot& plot, const PanelFrame& f) {
  const PixelRect& a = f.area;
  for (const Annotation& note : plot.annotations()) {
    const PixelPoint p{f.x(note.x), f.y(note.y)};
    if (!a.contains(p)) continue;
    svg.begin("circle")
        .attr("cx", p.x)
        .attr("cy", p.y)
        .attr("r", 2.5)
        .attr("fill", style::text_color)
        .empty();
    const AnnotationText t = annotation_text(p, note.text, a);
    svg.begin("text")
        .attr("class", "annotation")
        .attr("x", t.x)
        .attr("y", t.y)
        .attr("text-anchor", t.anchor_end ? "end" : "start")
        .attr("font-size", style::note_font)
        .attr("fill", style::text_color);
    with_halo(svg).text(note.text);
  }
}

// Highlighted points: a ring in the highlight's colour with the explanation as its tooltip.
void draw_highlights(SvgWriter& svg, const Plot& plot, const PanelFrame& f) {
  for (const Highlight& h : plot.highlights()) {
    const PixelPoint p{f.x(h.x), f.y(h.y)};
    if (!f.area.contains(p)) continue;
    svg.begin("circle")
        .attr("class", "highlight")
        .attr("cx", p.x)
        .attr("cy", p.y)
        .attr("r", style::highlight_radius)
        .attr("fill", "none")
        .attr("stroke", or_default(h.color, style::highlight_color))
        .attr("stroke-width", style::reference_width * 1.5)
        .open();
    svg.begin("title").text(h.text);
    svg.close();
  }
}

bool no_data(const std::vector<DrawnSeries>& drawn) {
  return std::all_of(drawn.begin(), drawn.end(),
                     [](const DrawnSeries& d) { return d.runs.empty(); });
}

LegendEntry::Kind legend_kind(Series::Style s) {
  switch (s) {
    case Series::Style::line:
      return LegendEntry::Kind::line;
    case Series::Style::dashed:
      return LegendEntry::Kind::dashed;
    case Series::Style::markers:
      return LegendEntry::Kind::markers;
    case Series::Style::line_markers:
      return LegendEntry::Kind::line_markers;
  }
  return LegendEntry::Kind::line;
}

Legend panel_legend(const Plot& plot, const std::vector<DrawnSeries>& drawn) {
  std::vector<LegendEntry> entries;
  for (const DrawnSeries& d : drawn)
    if (!d.series->label.empty())
      entries.push_back({legend_kind(d.series->style), legend_label(d), d.color, d.shape});
  for (const Band& band : plot.bands())
    if (!band.label.empty())
      entries.push_back(
          {LegendEntry::Kind::band, band.label, or_default(band.color, style::band_color)});
  return make_legend(entries);
}

// Everything drawn in the plot area that a legend must leave visible: the data, annotations with
// their text, highlight rings, reference-line labels, the "no data" note.
LegendObstacles legend_obstacles(const Plot& plot, const std::vector<DrawnSeries>& drawn,
                                 const PanelFrame& f) {
  LegendObstacles out;
  for (const DrawnSeries& d : drawn) {
    if (draws_line(d.series->style))
      out.lines.insert(out.lines.end(), d.runs.begin(), d.runs.end());
    for (const PixelPoint& p : d.markers)
      out.boxes.push_back(square_around(p, style::marker_radius));
  }
  const PixelRect& a = f.area;
  for (const Annotation& note : plot.annotations()) {
    const PixelPoint p{f.x(note.x), f.y(note.y)};
    if (!a.contains(p)) continue;
    out.boxes.push_back(square_around(p, 2.5));
    out.boxes.push_back(annotation_text(p, note.text, a).box);
  }
  for (const Highlight& h : plot.highlights()) {
    const PixelPoint p{f.x(h.x), f.y(h.y)};
    if (a.contains(p)) out.boxes.push_back(square_around(p, style::highlight_radius + 1));
  }
  for (const ReferenceLine& line : plot.vertical_lines()) {
    const double x = f.x(line.value);
    if (!line.label.empty() && x >= a.left && x <= a.right)
      out.boxes.push_back(vertical_label(x, a, line.label).box);
  }
  for (const ReferenceLine& line : plot.horizontal_lines()) {
    const double y = f.y(line.value);
    if (!line.label.empty() && y >= a.top && y <= a.bottom)
      out.boxes.push_back(horizontal_label_box(y, a, line.label));
  }
  if (no_data(drawn)) {
    const double cx = 0.5 * (a.left + a.right), cy = 0.5 * (a.top + a.bottom);
    const double w = text_width("no data", style::label_font);
    out.boxes.push_back({cx - w / 2, cy - style::label_font, cx + w / 2, cy + style::label_font});
  }
  return out;
}

}  // namespace

void draw_panel(SvgWriter& svg, const Plot& plot, const PanelFrame& frame) {
  const std::vector<DrawnSeries> drawn = map_series(plot, frame);
  svg.begin("g").attr("class", "panel").open();
  draw_bands(svg, plot, frame);
  draw_grid(svg, frame);
  draw_reference_lines(svg, plot, frame);
  draw_series(svg, drawn, frame.area);
  draw_frame(svg, plot, frame);
  draw_highlights(svg, plot, frame);
  draw_annotations(svg, plot, frame);
  if (no_data(drawn))
    svg.begin("text")
        .attr("class", "no-data")
        .attr("x", 0.5 * (frame.area.left + frame.area.right))
        .attr("y", 0.5 * (frame.area.top + frame.area.bottom))
        .attr("dy", "0.35em")
        .attr("text-anchor", "middle")
        .attr("font-size", style::label_font)
        .attr("fill", style::muted_text_color)
        .text("no data");
  const Legend legend = panel_legend(plot, drawn);
  if (!legend.empty()) {
    const LegendObstacles obstacles = legend_obstacles(plot, drawn, frame);
    std::optional<PixelPoint> place;
    if (frame.legend_outside)
      place = outside_legend_place(frame.area);
    else
      place = free_legend_place(legend, frame.area, obstacles);
    draw_legend(svg, legend,
                place.value_or(least_covering_legend_place(legend, frame.area, obstacles)));
  }
  svg.close();
}

PanelLegendFit panel_legend_fit(const Plot& plot, const PanelFrame& frame) {
  const std::vector<DrawnSeries> drawn = map_series(plot, frame);
  const Legend legend = panel_legend(plot, drawn);
  if (legend.empty()) return {};
  return {legend.width,
          free_legend_place(legend, frame.area, legend_obstacles(plot, drawn, frame)).has_value()};
}

}  // namespace polarform
