#include "export/svg_plot.h"

#include <algorithm>

#include "export/atomic_file.h"
#include "export/plot_layout.h"
#include "export/plot_legend.h"
#include "export/plot_panel.h"
#include "export/plot_style.h"
#include "export/svg_writer.h"

namespace polarform {

namespace {

// The smallest plot width worth keeping when making room for legends beside the plots.
constexpr double kMinPlotWidthBesideLegend = 240;

// The frames, with room right of the plots when a legend finds no place inside that hides
// nothing; then every legend that still hides something goes there.
std::vector<PanelFrame> lay_out_with_legends(const Figure& figure) {
  std::vector<PanelFrame> frames = lay_out_figure(figure);
  double widest = 0;
  bool any_outside = false;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const PanelLegendFit fit = panel_legend_fit(figure.panels()[i], frames[i]);
    widest = std::max(widest, fit.width);
    any_outside = any_outside || !fit.inside;
  }
  const double room = outside_legend_room(widest);
  if (!any_outside ||
      frames.front().area.right - frames.front().area.left - room < kMinPlotWidthBesideLegend)
    return frames;
  frames = lay_out_figure(figure, room);
  for (std::size_t i = 0; i < frames.size(); ++i)
    frames[i].legend_outside = !panel_legend_fit(figure.panels()[i], frames[i]).inside;
  return frames;
}

}  // namespace

std::string svg_document(const Figure& figure) {
  const std::vector<PanelFrame> frames = lay_out_with_legends(figure);
  const double width = figure.width(), height = figure.height();
  SvgWriter svg;
  const std::string size = svg_number(width) + " " + svg_number(height);
  svg.begin("svg")
      .attr("xmlns", "http://www.w3.org/2000/svg")
      .attr("width", width)
      .attr("height", height)
      .attr("viewBox", "0 0 " + size)
      .attr("font-family", plot_style::font_family)
      .open();
  svg.begin("rect").attr("width", width).attr("height", height).attr("fill", "white").empty();
  if (!figure.title.empty())
    svg.begin("text")
        .attr("class", "figure-title")
        .attr("x", width / 2)
        .attr("y", kFigurePadding + plot_style::figure_title_font)
        .attr("text-anchor", "middle")
        .attr("font-size", plot_style::figure_title_font)
        .attr("font-weight", "600")
        .attr("fill", plot_style::text_color)
        .text(figure.title);
  for (std::size_t i = 0; i < frames.size(); ++i) draw_panel(svg, figure.panels()[i], frames[i]);
  svg.close();
  return svg.str();
}

void save_svg(const Figure& figure, const std::filesystem::path& path) {
  write_file_atomically(path, svg_document(figure));
}

}  // namespace polarform
