#include "export/figure.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

// Empty (palette), "#rgb", "#rrggbb" or a CSS colour name.
void check_color(const std::string& color, const std::string& what) {
  const auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
  const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  const bool ok = color.empty() ||
                  (color[0] == '#' && (color.size() == 4 || color.size() == 7) &&
                   std::all_of(color.begin() + 1, color.end(), hex)) ||
                  std::all_of(color.begin(), color.end(), letter);
  if (!ok)
    throw InputError(what + ": color must be \"#rrggbb\", \"#rgb\" or a CSS colour name, got \"" +
                     color + "\"");
}

void check_finite(double v, const std::string& what) {
  if (!std::isfinite(v)) throw InputError(what + " must be finite, got " + format_round_trip(v));
}

}  // namespace

void Plot::add(Series series) {
  const std::string what = "Series '" + series.label + "'";
  if (series.x.size() != series.y.size())
    throw InputError(what + ": x has " + std::to_string(series.x.size()) + " values but y has " +
                     std::to_string(series.y.size()) + "; they must pair up");
  check_color(series.color, what);
  series_.push_back(std::move(series));
}

void Plot::add_vertical_line(double x, std::string label, std::string color, int handle) {
  check_finite(x, "add_vertical_line: x");
  check_color(color, "add_vertical_line");
  vertical_lines_.push_back({x, std::move(label), std::move(color), handle});
}

void Plot::add_horizontal_line(double y, std::string label, std::string color) {
  check_finite(y, "add_horizontal_line: y");
  check_color(color, "add_horizontal_line");
  horizontal_lines_.push_back({y, std::move(label), std::move(color)});
}

void Plot::add_band(double x0, double x1, std::string label, std::string color) {
  check_finite(x0, "add_band: x0");
  check_finite(x1, "add_band: x1");
  if (!(x0 < x1))
    throw InputError("add_band: x0 must be less than x1, got " + format_round_trip(x0) + " and " +
                     format_round_trip(x1));
  check_color(color, "add_band");
  bands_.push_back({x0, x1, std::move(label), std::move(color)});
}

void Plot::add_highlight(double x, double y, std::string text, std::string color) {
  check_finite(x, "add_highlight: x");
  check_finite(y, "add_highlight: y");
  if (text.empty()) throw InputError("add_highlight: text must not be empty");
  check_color(color, "add_highlight");
  highlights_.push_back({x, y, std::move(text), std::move(color)});
}

void Plot::add_annotation(double x, double y, std::string text) {
  check_finite(x, "add_annotation: x");
  check_finite(y, "add_annotation: y");
  if (text.empty()) throw InputError("add_annotation: text must not be empty");
  annotations_.push_back({x, y, std::move(text)});
}

Figure::Figure(double width, double height) : width_(width), height_(height) {
  if (!(std::isfinite(width) && width >= 200))
    throw InputError("Figure: width must be at least 200 px, got " + format_round_trip(width));
  if (!(std::isfinite(height) && height >= 150))
    throw InputError("Figure: height must be at least 150 px, got " + format_round_trip(height));
}

Plot& Figure::add_panel() { return panels_.emplace_back(); }

}  // namespace polarform
