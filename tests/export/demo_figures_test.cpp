// Demo figures written to <build>/plot_demo/ for a visual check: an SVAJ stack of a cycloidal
// rise and a harmonic return, a log-log tolerance study, a cam profile with equal aspect, and a
// report.html embedding them. The test asserts the files hold what svg()/html() return.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "export/csv_writer.h"
#include "export/html_report.h"
#include "export/svg_plot.h"
#include "src/units.h"
#include "tests/export/svg_test_support.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

struct Svaj {
  std::vector<double> theta, s, v, a, j;  // theta in degrees, derivatives per radian
};

// Rise h over 0..120° (cycloidal), dwell, return over 180..300° (simple harmonic), dwell.
// Each segment is sampled with both ends, so jumps at the boundaries are drawn vertically.
Svaj cam_motion() {
  const double h = 10, beta = 120 * kRadiansPerDegree;
  Svaj m;
  const auto add = [&](double theta, double s, double v, double a, double j) {
    m.theta.push_back(theta), m.s.push_back(s), m.v.push_back(v), m.a.push_back(a),
        m.j.push_back(j);
  };
  for (int i = 0; i <= 480; ++i) {
    const double x = i / 480.0, w = 2 * kPi * x;
    add(120 * x, h * (x - std::sin(w) / (2 * kPi)), h / beta * (1 - std::cos(w)),
        2 * kPi * h / (beta * beta) * std::sin(w),
        4 * kPi * kPi * h / std::pow(beta, 3) * std::cos(w));
  }
  for (int i = 0; i <= 60; ++i) add(120 + i, h, 0, 0, 0);
  for (int i = 0; i <= 480; ++i) {
    const double x = i / 480.0, w = kPi * x;
    add(180 + 120 * x, h / 2 * (1 + std::cos(w)), -kPi * h / (2 * beta) * std::sin(w),
        -kPi * kPi * h / (2 * beta * beta) * std::cos(w),
        std::pow(kPi, 3) * h / (2 * std::pow(beta, 3)) * std::sin(w));
  }
  for (int i = 0; i <= 60; ++i) add(300 + i, 0, 0, 0, 0);
  return m;
}

Figure svaj_figure(const Svaj& m) {
  Figure figure(820, 860);
  figure.title = "SVAJ: cycloidal rise, harmonic return (h = 10 mm)";
  figure.shared_x = true;
  const std::vector<double>* curves[] = {&m.s, &m.v, &m.a, &m.j};
  const char* labels[] = {"s [mm]", "v [mm/rad]", "a [mm/rad\u00B2]", "j [mm/rad\u00B3]"};
  for (int k = 0; k < 4; ++k) {
    Plot& p = figure.add_panel();
    p.y_label = labels[k];
    if (k == 0) {
      p.x_label = "cam angle \u03B8 [deg]";
      p.x_range = AxisRange{0, 360};
      p.x_tick_step = 30;
    }
    p.add({"", m.theta, *curves[k]});
    const char* names[] = {"rise end", "return start", "return end"};
    const double boundaries[] = {120, 180, 300};
    for (int b = 0; b < 3; ++b) p.add_vertical_line(boundaries[b], k == 0 ? names[b] : "");
    // The harmonic return jumps in acceleration at its ends; every segment end jumps in jerk.
    const std::vector<double> jumps =
        k == 2 ? std::vector<double>{180, 300} : std::vector<double>{0, 120, 180, 300};
    if (k >= 2) {
      for (const double at : jumps)
        p.add_band(std::max(0.0, at - 3), at + 3, k == 2 ? "acceleration jump" : "jerk jump",
                   "#D55E00");
      p.add_horizontal_line(0);
    }
  }
  return figure;
}

Figure tolerance_study() {
  Figure figure(720, 460);
  Plot& p = figure.add_panel();
  p.title = "Control points needed for a tolerance";
  p.x_label = "tolerance \u03B5 [mm]";
  p.y_label = "control points";
  p.log_x = p.log_y = true;
  const struct {
    const char* name;
    double c, k;
  } methods[] = {{"RQB base circle", 6.2, 1.0 / 3},
                 {"quartic base circle", 5.1, 1.0 / 5},
                 {"cubic least squares", 3.4, 1.0 / 4}};
  for (const auto& method : methods) {
    Series s{method.name, {}, {}, Series::Style::line_markers};
    for (int i = 0; i <= 10; ++i) {
      const double eps = std::pow(10.0, -6 + 0.5 * i);
      s.x.push_back(eps);
      s.y.push_back(std::round(method.c * std::pow(eps, -method.k)));
    }
    p.add(std::move(s));
  }
  p.add_vertical_line(1e-3, "default \u03B5");
  return figure;
}

Figure profile(const Svaj& m) {
  Figure figure(640, 640);
  Plot& p = figure.add_panel();
  p.title = "Cam profile (base radius 40 mm)";
  p.x_label = "x [mm]";
  p.y_label = "y [mm]";
  p.equal_aspect = true;
  Series outline{"pitch curve", {}, {}}, base{"base circle", {}, {}, Series::Style::dashed};
  for (std::size_t i = 0; i < m.theta.size(); ++i) {
    const double r = 40 + m.s[i], t = m.theta[i] * kRadiansPerDegree;
    outline.x.push_back(r * std::cos(t));
    outline.y.push_back(r * std::sin(t));
  }
  for (int i = 0; i <= 72; ++i) {
    const double t = i * 5 * kRadiansPerDegree;
    base.x.push_back(40 * std::cos(t));
    base.y.push_back(40 * std::sin(t));
  }
  // A stand-in control polygon: every 40th outline point, pushed slightly outwards.
  Series polygon{"control polygon", {}, {}, Series::Style::dashed, "#777777"};
  for (std::size_t i = 0; i < outline.x.size(); i += 40) {
    polygon.x.push_back(1.03 * outline.x[i]);
    polygon.y.push_back(1.03 * outline.y[i]);
  }
  Series ends{"segment ends", {}, {}, Series::Style::markers};
  for (const double theta : {0.0, 120.0, 180.0, 300.0}) {
    const double r = theta > 100 && theta < 200 ? 50 : 40;
    ends.x.push_back(r * std::cos(theta * kRadiansPerDegree)),
        ends.y.push_back(r * std::sin(theta * kRadiansPerDegree));
  }
  p.add(std::move(outline));
  p.add(std::move(base));
  p.add(std::move(polygon));
  p.add(std::move(ends));
  p.add_annotation(0, 0, "centre");
  return figure;
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(DemoFigures, WriteSvajStudyProfileAndReport) {
  const fs::path dir = fs::path(POLARFORM_BINARY_DIR) / "plot_demo";
  fs::create_directories(dir);
  const Svaj motion = cam_motion();
  const Figure figures[] = {svaj_figure(motion), tolerance_study(), profile(motion)};
  const char* names[] = {"svaj.svg", "tolerance_study.svg", "profile.svg"};
  HtmlReport report("Demo cam: plots for review");
  report.add_key_figures({{"lift", "10 mm"}, {"base radius", "40 mm"}, {"samples", "1084"}});
  for (int i = 0; i < 3; ++i) {
    const std::string svg = svg_document(figures[i]);
    save_svg(figures[i], dir / names[i]);
    EXPECT_EQ(read(dir / names[i]), svg);
    report.add_svg(svg, names[i]);
  }
  report.save(dir / "report.html");
  EXPECT_EQ(read(dir / "report.html"), report.html());

  CsvWriter csv({"theta [deg]", "s [mm]", "v [mm/rad]", "a [mm/rad^2]", "j [mm/rad^3]"});
  for (std::size_t i = 0; i < motion.theta.size(); ++i)
    csv.row({motion.theta[i], motion.s[i], motion.v[i], motion.a[i], motion.j[i]});
  csv.save(dir / "svaj.csv");
  EXPECT_EQ(csv.rows(), 481u + 61u + 481u + 61u);

  // The SVAJ stack: four aligned panels over 0..360° with ticks every 30°.
  const test::ParsedSvg svaj(svg_document(figures[0]));
  EXPECT_EQ(svaj.all("plot-area").size(), 4u);
  EXPECT_EQ(svaj.all("x-tick").size(), 13u);
  EXPECT_EQ(svaj.all("band").size(), 6u);
}

}  // namespace
}  // namespace polarform
