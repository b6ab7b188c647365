// The figure model of polarform: what a plot shows, independent of where it is drawn. A Figure is
// a vertical stack of Plot panels (optionally sharing the x axis, as in SVAJ diagrams); a Plot
// holds line and marker series, reference lines, highlighted bands, highlighted points with an
// explanation, and annotations, on linear or log axes. The jobs build figures; export/svg_plot
// renders them as SVG files and the studio's plot canvas draws the same figures on screen.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace polarform {

struct AxisRange {
  double min = 0;
  double max = 1;
};

struct Series {
  enum class Style { line, markers, line_markers, dashed };
  std::string label;         // legend text; empty keeps the series out of the legend
  std::vector<double> x, y;  // equal lengths; NaN or inf, or <= 0 on a log axis, leaves a gap
  Style style = Style::line;
  std::string color{};  // "#rrggbb", "#rgb" or a CSS colour name; empty: next palette colour
};

struct ReferenceLine {
  double value;
  std::string label;  // drawn beside the line
  std::string color;  // empty: grey
  // >= 0: an interactive view lets the user drag the line along its axis and reports this
  // handle with the new position (a segment boundary of a cam); static drawings ignore it.
  int handle = -1;
};

struct Band {
  double x0, x1;
  std::string label;  // legend text; empty keeps the band out of the legend
  std::string color;  // empty: grey; drawn translucent
};

// A point singled out with its explanation (a discontinuity, a violated limit): circled, the
// text shown when the reader points at it (a tooltip in SVG viewers and in the studio).
struct Highlight {
  double x, y;
  std::string text;
  std::string color;  // empty: the error colour
};

struct Annotation {
  double x, y;
  std::string text;
};

class Plot {
 public:
  std::string title;
  std::string x_label, y_label;  // with units: "cam angle θ [deg]", "s [mm]"
  bool log_x = false, log_y = false;
  bool equal_aspect = false;  // widens one range so a unit has the same length on both axes
  std::optional<AxisRange> x_range, y_range;       // default: x fits the data, y adds 5 % margins
  std::optional<double> x_tick_step, y_tick_step;  // default: 1-2-5 steps, decades on log axes

  // Each add validates its input and throws InputError naming the field.
  void add(Series series);
  void add_vertical_line(double x, std::string label = {}, std::string color = {}, int handle = -1);
  void add_horizontal_line(double y, std::string label = {}, std::string color = {});
  void add_band(double x0, double x1, std::string label = {}, std::string color = {});
  void add_highlight(double x, double y, std::string text, std::string color = {});
  void add_annotation(double x, double y, std::string text);

  const std::vector<Series>& series() const { return series_; }
  const std::vector<ReferenceLine>& vertical_lines() const { return vertical_lines_; }
  const std::vector<ReferenceLine>& horizontal_lines() const { return horizontal_lines_; }
  const std::vector<Band>& bands() const { return bands_; }
  const std::vector<Highlight>& highlights() const { return highlights_; }
  const std::vector<Annotation>& annotations() const { return annotations_; }

 private:
  std::vector<Series> series_;
  std::vector<ReferenceLine> vertical_lines_, horizontal_lines_;
  std::vector<Band> bands_;
  std::vector<Highlight> highlights_;
  std::vector<Annotation> annotations_;
};

class Figure {
 public:
  // Size of the drawing in pixels, at least 200 x 150.
  explicit Figure(double width = 800, double height = 500);

  std::string title;
  // Panels share the x axis of the first panel (x_label, log_x, x_range, x_tick_step; the range
  // covers all panels' data); tick labels and the x label appear under the last panel only.
  bool shared_x = false;

  // A new panel below the existing ones; the reference stays valid as panels are added.
  Plot& add_panel();
  const std::deque<Plot>& panels() const { return panels_; }
  double width() const { return width_; }
  double height() const { return height_; }

 private:
  double width_, height_;
  std::deque<Plot> panels_;
};

}  // namespace polarform
