// The key figures of a cam (jobs/cam/cam_key_figures.h) on the roller example against closed
// forms: a cycloidal rise of h = 20 mm over β = 90° at 300 rev/min peaks at v = 2h/β = 80/π mm/rad
// (0.8 m/s) at 135°, a = 2πh/β² = 160/π mm/rad² (16π m/s²) at 112.5°, j = 4π²h/β³ = 640/π mm/rad³
// (640π² m/s³) at 90°; report.html and the CLI state the same lines first.
#include "jobs/cam/cam_key_figures.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <string>

#include "tests/support/jobs/cam_job_support.h"

namespace polarform {
namespace {

using namespace cam_job_test;
using std::numbers::pi;

const KeyFigure& figure(const std::vector<KeyFigure>& figures, const std::string& name) {
  for (const KeyFigure& f : figures)
    if (f.name == name) return f;
  throw std::runtime_error("no key figure " + name);
}

// "T unit (R unit) at θ = A°" -> {T, R, A}.
std::array<double, 3> peak_numbers(const std::string& text) {
  std::array<double, 3> v{};
  const std::size_t open = text.find('('), at = text.find("θ = ");
  v[0] = std::stod(text);
  v[1] = std::stod(text.substr(open + 1));
  v[2] = std::stod(text.substr(at + std::string("θ = ").size()));
  return v;
}

TEST(CamKeyFigures, PeaksInTimeUnitsAndPerRadianEqualTheClosedForms) {
  const CamJobResult& r = example("roller").result;
  const std::vector<KeyFigure> results = cam_key_results(r.design, r.analysis, &r.conversion);
  const auto v = peak_numbers(figure(results, "peak velocity").value);
  EXPECT_NEAR(v[0], 0.8, 1e-5);
  EXPECT_NEAR(v[1], 80 / pi, 1e-4);
  EXPECT_NEAR(v[2], 135.0, 1e-3);
  const auto a = peak_numbers(figure(results, "peak acceleration").value);
  EXPECT_NEAR(a[0], 16 * pi, 1e-4);
  EXPECT_NEAR(a[1], 160 / pi, 1e-4);
  EXPECT_NEAR(a[2], 112.5, 1e-3);
  const auto j = peak_numbers(figure(results, "peak jerk").value);
  EXPECT_NEAR(j[0], 640 * pi * pi, 1e-2);
  EXPECT_NEAR(j[1], 640 / pi, 1e-3);
  EXPECT_NE(figure(results, "peak velocity").value.find(" m/s ("), std::string::npos);
  EXPECT_NE(figure(results, "peak jerk").value.find(" m/s³ ("), std::string::npos);
  EXPECT_NE(figure(results, "max pressure angle").value.find(", limit 30°"), std::string::npos);
  EXPECT_EQ(figure(results, "undercut").value, "none");
  EXPECT_EQ(figure(results, "stroke").value, "20 mm");
}

TEST(CamKeyFigures, InputsStateTheDesignAndEverySegment) {
  const CamJobResult& r = example("roller").result;
  const std::vector<KeyFigure> inputs = cam_design_inputs(r.design);
  EXPECT_EQ(figure(inputs, "cam").value,
            "plate cam, base radius 40 mm, roller follower, roller radius 10 mm");
  EXPECT_EQ(figure(inputs, "speed").value, "300 rev/min, counter-clockwise");
  EXPECT_EQ(figure(inputs, "segment 'segment 2'").value,
            "rise, cycloidal, lift 20 mm, θ 90° to 180°");
  EXPECT_EQ(figure(inputs, "segment 'segment 3'").value, "dwell, θ 180° to 240°");
  EXPECT_EQ(inputs.size(), 6u);
}

// report.html opens with the design and the key results, before any plot.
TEST(CamKeyFigures, ReportHtmlStartsWithThem) {
  const ExampleRun& run = example("roller");
  const std::string html = slurp(run.dir / "report.html");
  const std::size_t design = html.find(">Design<"), results = html.find(">Key results<"),
                    svg = html.find("<svg");
  ASSERT_NE(design, std::string::npos);
  ASSERT_NE(results, std::string::npos);
  EXPECT_LT(design, results);
  EXPECT_LT(results, svg);
  for (const KeyFigure& f :
       cam_key_results(run.result.design, run.result.analysis, &run.result.conversion))
    EXPECT_NE(html.find(f.name), std::string::npos) << f.name;
  EXPECT_NE(html.find("rise, cycloidal, lift 20 mm"), std::string::npos);
}

}  // namespace
}  // namespace polarform
