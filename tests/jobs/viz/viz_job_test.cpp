// The viz job (Bae 2002, §5.3): grid files parsed strictly with errors naming the line, the field
// surface S = (s·F + d)·B reproducing the values as radii, and the bundled example grid.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>

#include "jobs/viz/viz_outputs.h"
#include "jobs/viz/viz_plots.h"
#include "src/error.h"
#include "tests/support/jobs/job_test_support.h"

namespace polarform {
namespace {

using test::example;
using test::files_in;
using test::read_json;
using test::scratch_dir;

TEST(VizGrid, ParsesEitherSetUpAndNamesBadLines) {
  std::string cylinder = "theta_deg z_mm T_K  # a comment\n";
  for (int i = 0; i < 16; ++i)
    cylinder += std::to_string(22.5 * i) + " " + std::to_string(i % 4) + " 300\n";
  const ScalarGrid c = parse_scalar_grid(cylinder, "g");
  EXPECT_EQ(c.setup, GridSetup::cylindrical);
  EXPECT_EQ(c.value_name, "T_K");
  EXPECT_EQ(c.theta.size(), 16);
  EXPECT_NEAR(c.theta[4], std::numbers::pi / 2, 1e-15);
  try {
    std::string text = "p,phi_deg,theta_deg\n";
    for (int i = 0; i < 20; ++i) text += "1," + std::to_string(i) + ",0\n";
    text += "1,200,0\n";  // line 22
    parse_scalar_grid(text, "grid.csv");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grid.csv:22:"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_scalar_grid("a,b,c\n1,2,3\n", "g"), InputError);
  try {
    parse_scalar_grid("p phi_deg theta_deg\n1 2 x\n", "g");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("g:2: theta_deg 'x'"), std::string::npos) << e.what();
  }
}

TEST(VizJob, ExampleGridIsShownWithinItsFitError) {
  const VizJobResult r = run_viz_job(example("scans/sphere_grid.csv"));
  EXPECT_EQ(r.grid.setup, GridSetup::spherical);
  EXPECT_EQ(r.grid.value.size(), 684);
  EXPECT_EQ(r.offset, 0.0);  // every value is positive: the radius is the value
  // The radius of S at a data point's angles is s·F + d, i.e. the fitted value.
  EXPECT_LT(r.field.fit_error.max, 0.2);  // kPa, of a 40 kPa range on a 12 x 12 net
  const auto dir = scratch_dir();
  write_viz_outputs(r, dir);
  EXPECT_EQ(files_in(dir),
            (std::set<std::string>{"control_values.csv", "preview.svg", "report.html",
                                   "report.json", "surface.igs", "surface.stp", "surface.x3d"}));
  const nlohmann::json j = read_json(dir / "report.json");
  EXPECT_EQ(j["setup"], "spherical");
  EXPECT_EQ(j["value"], "pressure_kPa");
  EXPECT_NEAR(j["value_range"][0].get<double>(), 80.0, 1e-9);
  EXPECT_NEAR(j["value_range"][1].get<double>(), 120.0, 1e-9);
}

// A curve along θ that wraps through 360° is drawn up to one edge and on from the other: no line
// back across the panel, and no gap at the seam.
TEST(VizJob, CurvesAlongTheAzimuthBreakAtTheSeam) {
  const Figure fig = viz_preview_figure(run_viz_job(example("scans/sphere_grid.csv")));
  int fitted = 0;
  for (const Series& s : fig.panels().front().series()) {
    if (s.style != Series::Style::line) continue;
    ++fitted;
    double lo = 360, hi = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i])) continue;
      lo = std::min(lo, s.x[i]);
      hi = std::max(hi, s.x[i]);
      if (i > 0 && std::isfinite(s.x[i - 1])) {
        EXPECT_LT(std::abs(s.x[i] - s.x[i - 1]), 10.0) << s.label << " at " << s.x[i];
      }
    }
    EXPECT_LT(lo, 1e-9) << s.label;
    EXPECT_GT(hi, 360 - 1e-9) << s.label;
  }
  EXPECT_EQ(fitted, 4);
}

TEST(VizJob, ConstantFieldIsASphereOfThatRadius) {
  ScalarGrid g;
  g.setup = GridSetup::spherical;
  g.value_name = "p";
  const int n = 19 * 36;
  g.value = Eigen::VectorXd::Constant(n, 7.0);
  g.phi.resize(n);
  g.theta.resize(n);
  for (int i = 0; i < 19; ++i)
    for (int k = 0; k < 36; ++k)
      g.phi[i * 36 + k] = i * std::numbers::pi / 18,
                     g.theta[i * 36 + k] = k * std::numbers::pi / 18;
  VizJobOptions o;
  o.scale = 2.0;
  o.offset = 1.0;
  const VizJobResult r = run_viz_job(g, "constant", o);
  for (double u : {0.1, 0.5, 0.9})
    for (double v : {0.2, 0.7}) {
      const NurbsSurface& S = r.field.surface;
      const double uu = S.front_u() + u * (S.back_u() - S.front_u()),
                   vv = S.front_v() + v * (S.back_v() - S.front_v());
      EXPECT_NEAR(S.point(uu, vv).norm(), 15.0, 1e-9);  // 2·7 + 1
    }
  EXPECT_THROW(run_viz_job(g, "constant", VizJobOptions{{}, {}, 0.0, {}, Closure::automatic, 2}),
               InputError);
}

}  // namespace
}  // namespace polarform
