// SVG plots read back with tinyxml2: data land where the axis transform says, ticks are nice and
// cover the range, log ticks are decades, gaps, decimation, clipping, escaping, determinism.
#include "export/svg_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "export/text_width.h"
#include "src/error.h"
#include "src/units.h"
#include "tests/export/svg_test_support.h"

namespace polarform {
namespace {

using test::ParsedSvg;
using test::XMLElement;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPx = 0.006;  // coordinates are written with two decimals

struct Axis {
  double lo, hi, from, to;
  bool log = false;
  double operator()(double v) const {
    const auto t = [&](double u) { return log ? std::log10(u) : u; };
    return from + (t(v) - t(lo)) / (t(hi) - t(lo)) * (to - from);
  }
};

std::vector<Polyline> series_paths(const ParsedSvg& svg, std::size_t index = 0) {
  const auto paths = svg.all("series");
  EXPECT_GT(paths.size(), index);
  return test::subpaths(paths.at(index)->Attribute("d"));
}

std::vector<std::pair<double, double>> tick_labels(const ParsedSvg& svg, const std::string& cls,
                                                   const XMLElement* scope = nullptr) {
  std::vector<std::pair<double, double>> ticks;  // value, pixel position
  for (const XMLElement* t : test::by_class(scope ? scope : svg.root(), cls))
    ticks.push_back(
        {test::label_value(t->GetText()), t->DoubleAttribute(cls == "x-tick" ? "x" : "y")});
  return ticks;
}

TEST(SvgPlot, KnownPointsLandWhereTheAxisTransformSays) {
  Figure figure(640, 400);
  Plot& plot = figure.add_panel();
  plot.x_range = AxisRange{0, 10};
  plot.y_range = AxisRange{-1, 1};
  plot.add({"data", {2.5, 7.5, 10}, {0.5, -0.5, 1}});
  const ParsedSvg svg(svg_document(figure));
  const auto frames = svg.all("plot-area");
  ASSERT_EQ(frames.size(), 1u);
  const PixelRect a = test::area_of(frames[0]);
  EXPECT_GT(a.right - a.left, 500);
  EXPECT_GT(a.bottom - a.top, 300);
  const std::vector<Polyline> pieces = series_paths(svg);
  ASSERT_EQ(pieces.size(), 1u);
  ASSERT_EQ(pieces[0].size(), 3u);
  const double w = a.right - a.left, h = a.bottom - a.top;
  EXPECT_NEAR(pieces[0][0].x, a.left + 0.25 * w, kPx);
  EXPECT_NEAR(pieces[0][0].y, a.bottom - 0.75 * h, kPx);
  EXPECT_NEAR(pieces[0][1].x, a.left + 0.75 * w, kPx);
  EXPECT_NEAR(pieces[0][1].y, a.bottom - 0.25 * h, kPx);
  EXPECT_NEAR(pieces[0][2].x, a.right, kPx);
  EXPECT_NEAR(pieces[0][2].y, a.top, kPx);
}

TEST(SvgPlot, TicksAreNiceCoverTheRangeAndSitOnTheirValues) {
  Figure figure(800, 450);
  Plot& plot = figure.add_panel();
  std::vector<double> x, y;
  for (int i = 0; i <= 360; ++i) {
    x.push_back(i);
    y.push_back(-3.7 + 15.9 * std::pow(std::sin(i * std::numbers::pi / 360), 2));
  }
  plot.add({"s", x, y});
  const ParsedSvg svg(svg_document(figure));
  const PixelRect a = test::area_of(svg.all("plot-area")[0]);
  // x fits the data exactly, y has 5 % margins.
  const Axis ax{0, 360, a.left, a.right};
  const double margin = 0.05 * 15.9;
  const Axis ay{-3.7 - margin, 12.2 + margin, a.bottom, a.top};
  for (const auto& [cls, axis] :
       {std::pair{std::string("x-tick"), ax}, std::pair{std::string("y-tick"), ay}}) {
    const auto ticks = tick_labels(svg, cls);
    ASSERT_GE(ticks.size(), 4u) << cls;
    const double step = ticks[1].first - ticks[0].first;
    const double mantissa = step / std::pow(10, std::floor(std::log10(step) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                std::abs(mantissa - 5) < 1e-9)
        << cls << " step " << step;
    for (std::size_t i = 0; i < ticks.size(); ++i) {
      const double v = ticks[i].first;
      EXPECT_NEAR(v / step, std::round(v / step), 1e-9) << cls;  // a multiple of the step
      if (i > 0) {
        EXPECT_NEAR(v - ticks[i - 1].first, step, 1e-9 * step) << cls;
      }
      EXPECT_GE(v, axis.lo - 1e-9);
      EXPECT_LE(v, axis.hi + 1e-9);
      EXPECT_NEAR(ticks[i].second, axis(v), kPx) << cls << " tick " << v;
    }
    // Covering: no room for another multiple of the step at either end.
    EXPECT_LT(ticks.front().first - step, axis.lo) << cls;
    EXPECT_GT(ticks.back().first + step, axis.hi) << cls;
  }
  // Neighbouring x labels keep clear of each other.
  const auto x_labels = svg.all("x-tick");
  for (std::size_t i = 1; i < x_labels.size(); ++i) {
    const double gap = x_labels[i]->DoubleAttribute("x") - x_labels[i - 1]->DoubleAttribute("x");
    const double half_widths =
        0.5 * (text_width(x_labels[i]->GetText(), 12) + text_width(x_labels[i - 1]->GetText(), 12));
    EXPECT_GT(gap, half_widths + 8);
  }
}

TEST(SvgPlot, LogAxesTickAtDecades) {
  Figure figure(700, 450);
  Plot& plot = figure.add_panel();
  plot.log_x = plot.log_y = true;
  plot.add({"quartic", {1e-6, 1e-4, 1e-2, 0.3}, {900, 130, 20, 7}, Series::Style::line_markers});
  const ParsedSvg svg(svg_document(figure));
  const PixelRect a = test::area_of(svg.all("plot-area")[0]);
  // With markers, x gets 3 % margins (in decades) so that end markers clear the frame.
  const double x_margin = std::pow(0.3 / 1e-6, 0.03);
  const Axis ax{1e-6 / x_margin, 0.3 * x_margin, a.left, a.right, true};
  const auto x_ticks = tick_labels(svg, "x-tick");
  ASSERT_GE(x_ticks.size(), 3u);
  for (const auto& [v, px] : x_ticks) {
    EXPECT_EQ(v, std::pow(10.0, std::round(std::log10(v)))) << v;  // an exact power of ten
    EXPECT_NEAR(px, ax(v), kPx);
  }
  EXPECT_EQ(x_ticks.front().first, 1e-6);
  EXPECT_EQ(x_ticks.back().first, 0.1);
  EXPECT_STREQ(svg.all("x-tick")[0]->GetText(), "10\u207B\u2076");
  // y: 7..900 widened by 5 % of the span in decades, to 5.49..1147.
  const auto y_ticks = tick_labels(svg, "y-tick");
  ASSERT_EQ(y_ticks.size(), 3u);
  EXPECT_EQ(y_ticks[0].first, 10);
  EXPECT_EQ(y_ticks[2].first, 1000);
  const double margin = std::pow(900.0 / 7, 0.05);
  const Axis ay{7 / margin, 900 * margin, a.bottom, a.top, true};
  for (const auto& [v, px] : y_ticks) EXPECT_NEAR(px, ay(v), kPx);
  // Minor ticks 2..9 in every decade: the tick path has far more marks than labels.
  const std::string ticks = svg.all("ticks")[0]->Attribute("d");
  EXPECT_GE(std::count(ticks.begin(), ticks.end(), 'M'), 8 * 5);
  EXPECT_EQ(svg.all("minor").size(), 1u);  // light grid at the minor ticks
}

TEST(SvgPlot, NonFiniteValuesBreakTheLineIntoSubpaths) {
  Figure figure;
  Plot& plot = figure.add_panel();
  plot.add({"gappy",
            {0, 1, 2, 3, 4, 5, 6},
            {0, 1, kNaN, 3, 4, std::numeric_limits<double>::infinity(), 6}});
  const ParsedSvg svg(svg_document(figure));
  const std::vector<Polyline> pieces = series_paths(svg);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(pieces[0].size(), 2u);
  EXPECT_EQ(pieces[1].size(), 2u);
  EXPECT_EQ(pieces[2].size(), 2u);  // a lone point drawn as a dot
  EXPECT_EQ(pieces[2][0], pieces[2][1]);
}

TEST(SvgPlot, NonPositiveValuesOnALogAxisAreDroppedAndCounted) {
  Figure figure;
  Plot& plot = figure.add_panel();
  plot.log_y = true;
  plot.add({"error", {0, 1, 2, 3, 4}, {1e-3, 0, 1e-4, -2, 1e-5}});
  const ParsedSvg svg(svg_document(figure));
  EXPECT_EQ(series_paths(svg).size(), 3u);
  const auto legend = svg.all("legend");
  ASSERT_EQ(legend.size(), 1u);
  EXPECT_STREQ(legend[0]->FirstChildElement("text")->GetText(),
               "error (2 points \u2264 0 omitted)");
}

TEST(SvgPlot, DecimationToPixelColumnsKeepsTheSpikes) {
  Figure figure(600, 300);
  Plot& plot = figure.add_panel();
  Series s{"signal", {}, {}};
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    s.x.push_back(i);
    s.y.push_back(std::sin(i * 1e-3));
  }
  s.y[123457] = 7.5;  // spikes of a single sample
  s.y[160001] = -4.25;
  plot.add(std::move(s));
  const std::string text = svg_document(figure);
  EXPECT_LT(text.size(), 120000u);
  const ParsedSvg svg(text);
  const PixelRect a = test::area_of(svg.all("plot-area")[0]);
  const std::vector<Polyline> pieces = series_paths(svg);
  std::size_t points = 0;
  double top = 1e9, bottom = -1e9;
  for (const Polyline& piece : pieces)
    for (const PixelPoint& p : piece) {
      ++points;
      top = std::min(top, p.y);
      bottom = std::max(bottom, p.y);
    }
  EXPECT_LE(points, 4 * static_cast<std::size_t>(a.right - a.left + 1));
  const double margin = 0.05 * (7.5 + 4.25);
  const Axis ay{-4.25 - margin, 7.5 + margin, a.bottom, a.top};
  EXPECT_NEAR(top, ay(7.5), kPx);
  EXPECT_NEAR(bottom, ay(-4.25), kPx);
}

TEST(SvgPlot, DataOutsideAFixedRangeAreClippedToThePlotArea) {
  Figure figure;
  Plot& plot = figure.add_panel();
  plot.y_range = AxisRange{0, 1};
  plot.add({"", {0, 1, 2, 3}, {0.5, 5, 0.5, 1e300}});
  const ParsedSvg svg(svg_document(figure));
  const PixelRect a = test::area_of(svg.all("plot-area")[0]);
  const std::vector<Polyline> pieces = series_paths(svg);
  ASSERT_EQ(pieces.size(), 2u);
  for (const Polyline& piece : pieces)
    for (const PixelPoint& p : piece) {
      EXPECT_GE(p.y, a.top - kPx);
      EXPECT_LE(p.y, a.bottom + kPx);
    }
  EXPECT_NEAR(pieces[0].back().y, a.top, kPx);  // leaves through the top edge
  const Axis ax{0, 3, a.left, a.right};
  // 0.5 -> 5 crosses y = 1 at x = 1/9.
  EXPECT_NEAR(pieces[0].back().x, ax(1.0 / 9), kPx);
}

TEST(SvgPlot, ConstantAndEmptySeriesStillDraw) {
  Figure figure;
  Plot& constant = figure.add_panel();
  constant.add({"flat", {0, 1, 2}, {5, 5, 5}});
  Plot& empty = figure.add_panel();
  empty.add({"nothing", {}, {}});
  const ParsedSvg svg(svg_document(figure));
  const auto panels = svg.all("panel");
  ASSERT_EQ(panels.size(), 2u);
  const PixelRect a = test::area_of(test::by_class(panels[0], "plot-area")[0]);
  const std::vector<Polyline> pieces = series_paths(svg);
  EXPECT_NEAR(pieces[0][0].y, 0.5 * (a.top + a.bottom), kPx);  // padded symmetrically
  const auto y_ticks = tick_labels(svg, "y-tick", panels[0]);
  EXPECT_TRUE(std::any_of(y_ticks.begin(), y_ticks.end(), [](auto t) { return t.first == 5; }));
  EXPECT_EQ(test::by_class(panels[1], "no-data").size(), 1u);
  EXPECT_EQ(test::by_class(panels[1], "series").size(), 0u);
  EXPECT_EQ(test::by_class(panels[0], "no-data").size(), 0u);
}

TEST(SvgPlot, SharedXStacksAlignAndLabelOnlyTheBottom) {
  Figure figure(800, 900);
  figure.shared_x = true;
  const char* names[] = {"s [mm]", "v [mm/rad]", "a [mm/rad\u00B2]", "j [mm/rad\u00B3]"};
  Plot& first_panel = figure.add_panel();
  first_panel.x_label = "cam angle \u03B8 [deg]";  // the first panel's x settings are shared
  for (int k = 0; k < 4; ++k) {
    Plot& p = k == 0 ? first_panel : figure.add_panel();
    p.y_label = names[k];
    p.add({"", {0, 90.0 * (k + 1)}, {0, std::pow(100.0, k)}});  // x data differ per panel
  }
  const ParsedSvg svg(svg_document(figure));
  const auto panels = svg.all("panel");
  ASSERT_EQ(panels.size(), 4u);
  const PixelRect first = test::area_of(test::by_class(panels[0], "plot-area")[0]);
  for (int k = 0; k < 4; ++k) {
    const PixelRect a = test::area_of(test::by_class(panels[k], "plot-area")[0]);
    EXPECT_EQ(a.left, first.left);
    EXPECT_EQ(a.right, first.right);
    EXPECT_EQ(test::by_class(panels[k], "x-tick").empty(), k < 3);
    // The common range is 0..360: each panel's last point is at x = 90 (k + 1).
    const Polyline line = test::subpaths(test::by_class(panels[k], "series")[0]->Attribute("d"))[0];
    const Axis common{0, 360, a.left, a.right};
    EXPECT_NEAR(line.back().x, common(90.0 * (k + 1)), kPx);
    if (k > 0) {
      EXPECT_GT(a.top, test::area_of(test::by_class(panels[k - 1], "plot-area")[0]).bottom);
    }
  }
  const auto x_label = svg.all("x-label");
  ASSERT_EQ(x_label.size(), 1u);
  EXPECT_STREQ(x_label[0]->GetText(), "cam angle \u03B8 [deg]");
  EXPECT_EQ(svg.all("y-label").size(), 4u);
  // The large values of the jerk panel get a common factor.
  ASSERT_EQ(test::by_class(panels[3], "y-factor").size(), 1u);
  EXPECT_STREQ(test::by_class(panels[3], "y-factor")[0]->GetText(), "\u00D710\u2076");
}

TEST(SvgPlot, EqualAspectDrawsACircleRound) {
  Figure figure(800, 400);
  Plot& plot = figure.add_panel();
  plot.equal_aspect = true;
  Series circle{"profile", {}, {}};
  for (int i = 0; i <= 360; ++i) {
    circle.x.push_back(30 + 20 * std::cos(i * kRadiansPerDegree));
    circle.y.push_back(-10 + 20 * std::sin(i * kRadiansPerDegree));
  }
  plot.add(std::move(circle));
  const ParsedSvg svg(svg_document(figure));
  double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
  for (const Polyline& piece : series_paths(svg))
    for (const PixelPoint& p : piece) {
      left = std::min(left, p.x), right = std::max(right, p.x);
      top = std::min(top, p.y), bottom = std::max(bottom, p.y);
    }
  EXPECT_NEAR(right - left, bottom - top, 0.02);
  EXPECT_GT(right - left, 250);  // fills the height
  // Ticks of the two axes have the same pixel spacing per unit.
  const auto x_ticks = tick_labels(svg, "x-tick");
  const auto y_ticks = tick_labels(svg, "y-tick");
  const double x_scale =
      (x_ticks[1].second - x_ticks[0].second) / (x_ticks[1].first - x_ticks[0].first);
  const double y_scale =
      (y_ticks[0].second - y_ticks[1].second) / (y_ticks[1].first - y_ticks[0].first);
  EXPECT_NEAR(x_scale, y_scale, 1e-2);
}

TEST(SvgPlot, ReferenceLinesBandsAndAnnotationsSitAtTheirValues) {
  Figure figure;
  Plot& plot = figure.add_panel();
  plot.x_range = AxisRange{0, 360};
  plot.y_range = AxisRange{0, 40};
  plot.add({"pressure angle", {0, 360}, {10, 20}});
  plot.add_vertical_line(120, "rise end");
  plot.add_horizontal_line(30, "limit 30\u00B0", "#D55E00");
  plot.add_band(170, 190, "jerk discontinuity", "#D55E00");
  plot.add_annotation(200, 25, "max");
  const ParsedSvg svg(svg_document(figure));
  const PixelRect a = test::area_of(svg.all("plot-area")[0]);
  const Axis ax{0, 360, a.left, a.right}, ay{0, 40, a.bottom, a.top};
  EXPECT_NEAR(test::subpaths(svg.all("vertical")[0]->Attribute("d"))[0][0].x, ax(120), kPx);
  EXPECT_NEAR(test::subpaths(svg.all("horizontal")[0]->Attribute("d"))[0][0].y, ay(30), kPx);
  const XMLElement* band = svg.all("band")[0];
  EXPECT_NEAR(band->DoubleAttribute("x"), ax(170), kPx);
  EXPECT_NEAR(band->DoubleAttribute("width"), ax(190) - ax(170), 2 * kPx);
  EXPECT_STREQ(svg.all("annotation")[0]->GetText(), "max");
  // Legend: the series and the band.
  int rows = 0;
  for (const XMLElement* t = svg.all("legend")[0]->FirstChildElement("text"); t;
       t = t->NextSiblingElement("text"))
    ++rows;
  EXPECT_EQ(rows, 2);
}

// A highlighted point is a ring at its value carrying its explanation as a tooltip (<title>), and
// the automatic y range makes room for it.
TEST(SvgPlot, HighlightsAreRingsWithTheirExplanation) {
  Figure figure;
  Plot& plot = figure.add_panel();
  plot.x_range = AxisRange{0, 360};
  plot.add({"jerk", {0, 90, 90, 360}, {0, 0, 200, 0}});
  plot.add_highlight(90, 250, "jerk jumps by 250 at 90°");
  plot.add_highlight(400, 0, "outside the x range: not drawn", "#0072B2");
  const ParsedSvg svg(svg_document(figure));
  const PixelRect a = test::area_of(svg.all("plot-area")[0]);
  const auto rings = svg.all("highlight");
  ASSERT_EQ(rings.size(), 1u);
  const XMLElement* ring = rings[0];
  EXPECT_STREQ(ring->Attribute("fill"), "none");
  EXPECT_STREQ(ring->Attribute("stroke"), "#D55E00");  // the default: the error colour
  EXPECT_STREQ(ring->FirstChildElement("title")->GetText(), "jerk jumps by 250 at 90°");
  const Axis ax{0, 360, a.left, a.right};
  EXPECT_NEAR(ring->DoubleAttribute("cx"), ax(90), kPx);
  // y fits 0..250 with 5 % margins, so the ring lies inside the plot area, below its top.
  EXPECT_GT(ring->DoubleAttribute("cy"), a.top);
  EXPECT_LT(ring->DoubleAttribute("cy"), a.top + 0.1 * (a.bottom - a.top));
}

TEST(SvgPlot, LegendAvoidsTheData) {
  Figure figure;
  Plot& plot = figure.add_panel();
  // A rising line through the top-right and bottom-left corners.
  plot.add({"rising", {0, 10}, {0, 10}});
  const ParsedSvg svg(svg_document(figure));
  const PixelRect a = test::area_of(svg.all("plot-area")[0]);
  const XMLElement* box = svg.all("legend")[0]->FirstChildElement("rect");
  EXPECT_NEAR(box->DoubleAttribute("x"), a.left + 8, kPx);  // top left is free
  EXPECT_NEAR(box->DoubleAttribute("y"), a.top + 8, kPx);
}

// Annotations in the free corners keep the legend away from them, as the data do.
TEST(SvgPlot, LegendAvoidsAnnotations) {
  Figure figure;
  Plot& plot = figure.add_panel();
  plot.add({"rising", {0, 10}, {0, 10}});
  plot.add_annotation(0.2, 9.8, "a note in the top left");
  plot.add_annotation(9.8, 0.2, "one in the bottom right");
  const ParsedSvg svg(svg_document(figure));
  const PixelRect a = test::area_of(svg.all("plot-area")[0]);
  const XMLElement* box = svg.all("legend")[0]->FirstChildElement("rect");
  // Top left and bottom right hold the notes, top right and bottom left the line: the middle of
  // the top edge is left.
  const double width = box->DoubleAttribute("width");
  EXPECT_NEAR(box->DoubleAttribute("x"), 0.5 * (a.left + a.right - width), kPx);
  EXPECT_NEAR(box->DoubleAttribute("y"), a.top + 8, kPx);
}

// When every place inside the plot hides something, the plot narrows and the legend stands
// beside it, level with its top.
TEST(SvgPlot, LegendGoesBesideAPlotWithNoFreePlace) {
  Figure figure;
  Plot& plot = figure.add_panel();
  Series cloud{"scattered points", {}, {}, Series::Style::markers};
  for (int i = 0; i <= 40; ++i)
    for (int k = 0; k <= 20; ++k) {
      cloud.x.push_back(i);
      cloud.y.push_back(k);
    }
  plot.add(std::move(cloud));
  const ParsedSvg svg(svg_document(figure));
  const PixelRect a = test::area_of(svg.all("plot-area")[0]);
  const XMLElement* box = svg.all("legend")[0]->FirstChildElement("rect");
  EXPECT_NEAR(box->DoubleAttribute("x"), a.right + 8, kPx);
  EXPECT_NEAR(box->DoubleAttribute("y"), a.top, kPx);
  EXPECT_LE(box->DoubleAttribute("x") + box->DoubleAttribute("width"), figure.width());
}

TEST(SvgPlot, TextIsEscapedAndOutputIsDeterministic) {
  const auto build = [] {
    Figure figure(640, 360);
    figure.title = "R(\u03B8) <fit> & \"error\"";
    Plot& plot = figure.add_panel();
    plot.x_label = "x < 1 & y > 2";
    plot.y_label = "e [mm]";
    plot.add({"a<b", {0, 1, 2}, {0.1, 0.3, 0.2}, Series::Style::dashed});
    plot.add({"c&d", {0, 1, 2}, {0.2, 0.1, 0.3}, Series::Style::markers});
    return svg_document(figure);
  };
  const std::string text = build();
  EXPECT_EQ(text, build());
  const ParsedSvg svg(text);
  EXPECT_STREQ(svg.all("figure-title")[0]->GetText(), "R(\u03B8) <fit> & \"error\"");
  EXPECT_STREQ(svg.all("x-label")[0]->GetText(), "x < 1 & y > 2");
  EXPECT_EQ(text.find("<fit>"), std::string::npos);
  const auto legend = svg.all("legend")[0];
  EXPECT_STREQ(legend->FirstChildElement("text")->GetText(), "a<b");
  EXPECT_STREQ(legend->LastChildElement("text")->GetText(), "c&d");
  // Palette colours in order; the dashed series is dashed.
  const auto series = svg.all("series");
  ASSERT_EQ(series.size(), 1u);
  EXPECT_STREQ(series[0]->Attribute("stroke"), "#0072B2");
  EXPECT_NE(series[0]->Attribute("stroke-dasharray"), nullptr);
  EXPECT_STREQ(svg.all("markers")[0]->Attribute("fill"), "#D55E00");
}

TEST(SvgPlot, BadInputIsRejectedWithTheField) {
  const auto message = [](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  Plot plot;
  EXPECT_NE(message([&] {
              plot.add({"s", {1, 2}, {1}});
            }).find("x has 2 values but y has 1"),
            std::string::npos);
  EXPECT_NE(message([&] {
              plot.add({"s", {1}, {1}, Series::Style::line, "red;"});
            }).find("color"),
            std::string::npos);
  EXPECT_NE(message([&] { plot.add_band(2, 1); }).find("x0 must be less than x1"),
            std::string::npos);
  EXPECT_NE(message([&] { plot.add_vertical_line(kNaN); }).find("x must be finite"),
            std::string::npos);
  EXPECT_NE(message([&] { plot.add_highlight(1, kNaN, "why"); }).find("add_highlight: y"),
            std::string::npos);
  EXPECT_NE(message([&] { plot.add_highlight(1, 2, ""); }).find("text must not be empty"),
            std::string::npos);
  EXPECT_NE(message([] { Figure(100, 400); }).find("width"), std::string::npos);
  EXPECT_NE(message([] { svg_document(Figure()); }).find("no panels"), std::string::npos);

  Figure figure;
  Plot& p = figure.add_panel();
  p.title = "Errors";
  p.add({"", {1, 2}, {1, 2}});
  p.log_y = true;
  p.y_range = AxisRange{0, 1};
  EXPECT_NE(
      message([&] { svg_document(figure); }).find("panel 1 ('Errors') y_range must be positive"),
      std::string::npos);
  p.log_y = false;
  p.y_range = AxisRange{3, 1};
  EXPECT_NE(message([&] {
              svg_document(figure);
            }).find("y_range must be finite with min < max, got [3, 1]"),
            std::string::npos);
  p.y_range.reset();
  p.x_tick_step = 1e-6;
  EXPECT_NE(message([&] { svg_document(figure); }).find("x_tick_step 1e-06 gives more than"),
            std::string::npos);
  p.x_tick_step.reset();
  p.equal_aspect = true;
  p.log_x = true;
  EXPECT_NE(message([&] { svg_document(figure); }).find("equal_aspect needs linear axes"),
            std::string::npos);

  Figure tall(400, 300);
  for (int k = 0; k < 6; ++k) tall.add_panel();
  EXPECT_NE(message([&] { svg_document(tall); }).find("height 300 px"), std::string::npos);
}

TEST(SvgPlot, UserTickStepGivesThoseMultiples) {
  Figure figure;
  Plot& plot = figure.add_panel();
  plot.x_range = AxisRange{0, 360};
  plot.x_tick_step = 45;
  plot.add({"", {0, 360}, {0, 1}});
  const ParsedSvg svg(svg_document(figure));
  const auto ticks = tick_labels(svg, "x-tick");
  ASSERT_EQ(ticks.size(), 9u);
  for (std::size_t i = 0; i < ticks.size(); ++i) EXPECT_EQ(ticks[i].first, 45.0 * i);
}

}  // namespace
}  // namespace polarform
