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
    // Rotated to run up along the line, ending near the top, on the line's left.
    const double tx = x - 4, ty = a.top + 4;
    svg.begin("text")
        .attr("class", "reference-label")
        .attr("x", tx)
        .attr("y", ty)
        .attr("text-anchor", "end")
        .attr("transform", "rotate(-90 " + svg_number(tx) + " " + svg_number(ty) + ")")
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
    const bool fits_right = p.x + 6 + text_width(note.text, style::note_font) <= a.right;
    const bool fits_above = p.y - 6 - style::note_font >= a.top;
    svg.begin("text")
        .attr("class", "annotation")
        .attr("x", fits_right ? p.x + 6 : p.x - 6)
        .attr("y", fits_above ? p.y - 6 : p.y + 6 + style::note_font)
        .attr("text-anchor", fits_right ? "start" : "end")
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

void draw_legend_for(SvgWriter& svg, const Plot& plot, const std::vector<DrawnSeries>& drawn,
                     const PanelFrame& f) {
  std::vector<LegendEntry> entries;
  std::vector<Polyline> obstacles;
  for (const DrawnSeries& d : drawn) {
    if (!d.series->label.empty())
      entries.push_back({legend_kind(d.series->style), legend_label(d), d.color, d.shape});
    if (draws_line(d.series->style))
      obstacles.insert(obstacles.end(), d.runs.begin(), d.runs.end());
    for (const PixelPoint& p : d.markers) obstacles.push_back({p});
  }
  for (const Band& band : plot.bands())
    if (!band.label.empty())
      entries.push_back(
          {LegendEntry::Kind::band, band.label, or_default(band.color, style::band_color)});
  draw_legend(svg, entries, f.area, obstacles);
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
  const bool no_data =
      std::all_of(drawn.begin(), drawn.end(), [](const DrawnSeries& d) { return d.runs.empty(); });
  if (no_data)
    svg.begin("text")
        .attr("class", "no-data")
        .attr("x", 0.5 * (frame.area.left + frame.area.right))
        .attr("y", 0.5 * (frame.area.top + frame.area.bottom))
        .attr("dy", "0.35em")
        .attr("text-anchor", "middle")
        .attr("font-size", style::label_font)
        .attr("fill", style::muted_text_color)
        .text("no data");
  draw_legend_for(svg, plot, drawn, frame);
  svg.close();
}

}  // namespace polarform
