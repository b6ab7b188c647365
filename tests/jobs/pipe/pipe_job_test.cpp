// The pipe job end to end: a U-shaped spine whose bound δ = d comes from its half circle and its
// legs' double normal; a radius below it gives the bundle, one at it is refused by name unless
// allowed; a straight spine gives an exact cylinder; a <pipe> project's rational circle spine gives
// the exact torus with 1/κ_max = R; the spine reader refuses bad files by line.
#include "jobs/pipe/pipe_job.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "jobs/pipe/pipe_outputs.h"
#include "jobs/project/pipe_project.h"
#include "src/error.h"
#include "src/io/spine_csv.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;

// Legs along x from x = 0 to 20 at y = ±d, joined by a half circle of radius d about (20, 0).
fs::path write_u_spine(const fs::path& dir, double d) {
  fs::create_directories(dir);
  const fs::path file = dir / "u.csv";
  std::ofstream out(file);
  out.precision(17);
  out << "x,y,z\n";
  for (int k = 0; k <= 40; ++k) out << 0.5 * k << ',' << -d << ",0\n";
  for (int k = 1; k < 60; ++k) {
    const double a = -std::numbers::pi / 2 + std::numbers::pi * k / 60;
    out << 20 + d * std::cos(a) << ',' << d * std::sin(a) << ",0\n";
  }
  for (int k = 40; k >= 0; --k) out << 0.5 * k << ',' << d << ",0\n";
  return file;
}

TEST(PipeJob, USpineBoundAndBundle) {
  const fs::path dir = fs::temp_directory_path() / "polarform_pipe_job_u";
  fs::remove_all(dir);
  const fs::path spine = write_u_spine(dir, 4.0);
  PipeJobOptions o;
  o.radius = 3.0;
  const PipeJobResult r = run_pipe_job(spine, o);
  // The cubic through the points overshoots the curvature where the legs meet the half circle
  // (κ jumps from 0 to 1/d there): the bound is local and somewhat below d; the legs' double
  // normal (2d) gives body–body d.
  EXPECT_EQ(r.bounds.limiting_mode, "local");
  EXPECT_LT(r.bounds.delta, 4.0);
  EXPECT_GT(r.bounds.delta, 3.0);
  EXPECT_NEAR(r.bounds.body_body, 4.0, 1e-3);  // the spline ripples slightly near its ends
  EXPECT_NEAR(r.bounds.local, 1 / r.curvature.kappa_max, 1e-12);
  EXPECT_TRUE(r.nonsingular);
  EXPECT_FALSE(r.pipe.exact);
  EXPECT_LE(r.pipe.max_error, r.tolerance);
  const std::vector<std::string> files = write_pipe_outputs(r, dir / "out");
  for (const char* f : {"pipe.igs", "pipe.stp", "pipe.x3d", "spine.igs", "curvature.svg",
                        "report.json", "report.html"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  std::ifstream in(dir / "out" / "report.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["command"], "pipe");
  EXPECT_TRUE(j["nonsingular"].get<bool>());
  EXPECT_NEAR(j["bounds_mm"]["delta"].get<double>(), r.bounds.delta, 1e-9);
}

// The helix (a = 2, c = 2, 1.5 turns: κ = a/(a² + c²) = 1/4, pitch 4π, so the local
// bound 4 limits): the cubic spline through the CSV's 601 points gives δ = 1/κ_max to 1e-12 and
// κ_max the closed form to 1e-4 (the spline's own error); 0.99 δ passes and every surface sample
// lies r from the exact helix within the tolerance plus the spline's own distance from the helix
// (measured here by Newton on the closed form); 1.01 δ is refused.
TEST(PipeJob, HelixBoundIsItsClosedFormCurvature) {
  const double a = 2, c = 2, end = 3 * std::numbers::pi;
  const fs::path dir = fs::temp_directory_path() / "polarform_pipe_job_helix";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path spine = dir / "helix.csv";
  {
    std::ofstream out(spine);
    out.precision(17);
    out << "x,y,z\n";
    for (int k = 0; k <= 600; ++k) {
      const double t = end * k / 600;
      out << a * std::cos(t) << ',' << a * std::sin(t) << ',' << c * t << '\n';
    }
  }
  const auto helix_distance = [&](const Eigen::Vector3d& p) {  // min over t of |p − H(t)|
    double best = 1e300, t_best = 0;
    for (int k = 0; k <= 2000; ++k) {
      const double t = -0.5 + (end + 1) * k / 2000;
      const double d = (p - Eigen::Vector3d(a * std::cos(t), a * std::sin(t), c * t)).norm();
      if (d < best) best = d, t_best = t;
    }
    for (int it = 0; it < 30; ++it) {  // Newton on f(t) = (H(t) − p)·H'(t)
      const Eigen::Vector3d h(a * std::cos(t_best), a * std::sin(t_best), c * t_best);
      const Eigen::Vector3d d1(-a * std::sin(t_best), a * std::cos(t_best), c);
      const Eigen::Vector3d d2(-a * std::cos(t_best), -a * std::sin(t_best), 0);
      t_best -= (h - p).dot(d1) / (d1.dot(d1) + (h - p).dot(d2));
    }
    return (p - Eigen::Vector3d(a * std::cos(t_best), a * std::sin(t_best), c * t_best)).norm();
  };
  PipeJobOptions o;
  o.radius = 1.0;
  const PipeJobResult probe = run_pipe_job(spine, o);
  EXPECT_EQ(probe.bounds.limiting_mode, "local");
  EXPECT_NEAR(probe.bounds.local, 1 / probe.curvature.kappa_max, 1e-12);
  EXPECT_NEAR(probe.curvature.kappa_max, a / (a * a + c * c), 1e-4 * 0.25);
  RecordProperty("kappa_max", std::to_string(probe.curvature.kappa_max));
  o.radius = 0.99 * probe.bounds.delta;
  const PipeJobResult r = run_pipe_job(spine, o);
  EXPECT_TRUE(r.nonsingular);
  EXPECT_LE(r.pipe.max_error, r.tolerance);
  double worst = 0.0;
  const NurbsSurface& S = r.pipe.surface;
  for (int i = 0; i <= 24; ++i)
    for (int j = 0; j <= 60; ++j) {
      const double u = S.front_u() + (S.back_u() - S.front_u()) * i / 24;
      const double v = S.front_v() + (S.back_v() - S.front_v()) * j / 60;
      worst = std::max(worst, std::abs(helix_distance(S.point(u, v)) - o.radius));
    }
  RecordProperty("helix_pipe_error", std::to_string(worst));
  EXPECT_LE(worst, r.tolerance + 1e-5);
  o.radius = 1.01 * probe.bounds.delta;
  EXPECT_THROW(run_pipe_job(spine, o), InputError);
}

TEST(PipeJob, ARadiusAtTheBoundIsAnInfeasibleDesign) {
  const fs::path dir = fs::temp_directory_path() / "polarform_pipe_job_bad";
  fs::remove_all(dir);
  const fs::path spine = write_u_spine(dir, 4.0);
  PipeJobOptions o;
  o.radius = 4.5;
  try {
    run_pipe_job(spine, o);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--radius 4.5 mm: the pipe self-intersects for radii at "
                                         "or beyond δ = "),
              std::string::npos)
        << e.what();
  }
  o.allow_self_intersection = true;
  const PipeJobResult r = run_pipe_job(spine, o);
  EXPECT_FALSE(r.nonsingular);
  EXPECT_EQ(r.warnings.size(), 1u);
  EXPECT_GT(r.pipe.max_error, 0.0);  // measured, not met: the pipe folds
}

TEST(PipeJob, AStraightSpineGivesAnExactCylinder) {
  const fs::path dir = fs::temp_directory_path() / "polarform_pipe_job_line";
  fs::create_directories(dir);
  {
    std::ofstream out(dir / "line.csv");
    out << "x,y,z\n0,0,0\n1,2,3\n2,4,6\n";
  }
  PipeJobOptions o;
  o.radius = 0.5;
  const PipeJobResult r = run_pipe_job(dir / "line.csv", o);
  EXPECT_TRUE(r.pipe.exact);
  EXPECT_TRUE(std::isinf(r.bounds.delta));
  for (int a = 0; a <= 20; ++a)
    for (int b = 0; b <= 20; ++b) {
      const NurbsSurface& s = r.pipe.surface;
      const Eigen::Vector3d p = s.point(s.front_u() + (s.back_u() - s.front_u()) * a / 20,
                                        s.front_v() + (s.back_v() - s.front_v()) * b / 20);
      const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
      EXPECT_NEAR((p - p.dot(axis) * axis).norm(), 0.5, 1e-12);
    }
}

// The full circle of radius R as the rational quadratic of NURBS Book Ex. 7.2 in a <pipe> project.
std::string circle_pipe_xml(double R, const std::string& closed) {
  std::string xml = "<pipe radius=\"5\" degree=\"2\" closed=\"" + closed +
                    "\" knots=\"0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1\">\n";
  const double x[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, y[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  for (int i = 0; i < 9; ++i)
    xml += "  <point at=\"" + std::to_string(R * x[i]) + "," + std::to_string(R * y[i]) + ",0\"" +
           (i % 2 ? " weight=\"0.70710678118654757\"" : "") + "/>\n";
  return xml + "</pipe>\n";
}

TEST(PipeJob, ARationalCircleSpineFromXmlGivesTheExactTorus) {
  constexpr double R = 30.0, r = 5.0;
  std::vector<std::string> warnings;
  const PipeProject project = parse_pipe_project(circle_pipe_xml(R, "auto"), "torus.xml", warnings);
  EXPECT_TRUE(warnings.empty());
  const PipeJobOptions o = pipe_job_options(project);
  EXPECT_EQ(o.radius, r);
  const PipeJobResult res = run_pipe_job("torus.xml", pipe_spine(project), o);
  EXPECT_TRUE(res.closed);
  EXPECT_FALSE(res.chord_length_parameter);
  EXPECT_EQ(res.points.cols(), 9);
  EXPECT_NEAR(1 / res.curvature.kappa_max, R, 1e-12 * R);
  EXPECT_NEAR(res.bounds.local, R, 1e-12 * R);
  EXPECT_NEAR(res.length, 2 * std::numbers::pi * R, 1e-9 * R);
  EXPECT_TRUE(res.nonsingular);
  ASSERT_TRUE(res.pipe.exact);
  const NurbsSurface& s = res.pipe.surface;
  EXPECT_EQ(s.degree_u(), 2);
  EXPECT_EQ(s.degree_v(), 2);
  double worst = 0.0;  // |(ρ − R)² + z² − r²| / r²: on the torus (closed form)
  for (int a = 0; a <= 40; ++a)
    for (int b = 0; b <= 40; ++b) {
      const Eigen::Vector3d p = s.point(s.front_u() + (s.back_u() - s.front_u()) * a / 40,
                                        s.front_v() + (s.back_v() - s.front_v()) * b / 40);
      const double rho = std::hypot(p.x(), p.y());
      worst = std::max(worst, std::abs((rho - R) * (rho - R) + p.z() * p.z() - r * r) / (r * r));
    }
  EXPECT_LT(worst, 1e-12);
}

TEST(PipeJob, ANurbsSpineClosedOnRequestMustMeetItself) {
  std::vector<std::string> warnings;
  PipeProject p = parse_pipe_project(circle_pipe_xml(30.0, "yes"), "c.xml", warnings);
  p.points.back() = Eigen::Vector3d(30, 0.5, 0);
  try {
    run_pipe_job("c.xml", pipe_spine(p), pipe_job_options(p));
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "c.xml: a closed spine (closed yes) but its ends are 0.5 mm apart");
  }
  p.closure = SpineClosure::automatic;  // open: its ends are apart, so its end circles meet
  PipeJobOptions o = pipe_job_options(p);
  o.allow_self_intersection = true;
  const PipeJobResult r = run_pipe_job("c.xml", pipe_spine(p), o);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.nonsingular);
  EXPECT_EQ(r.bounds.limiting_mode, "end-body");
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("(end-body, between t = 0 on the spine and t = "), std::string::npos)
      << r.warnings[0];
}

TEST(SpineCsv, RefusalsNameTheLine) {
  const auto refusal = [](const std::string& text) {
    try {
      parse_spine_csv(text, "s.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("x,y\n"), "s.csv:1: header 'x,y': expected 'x,y,z'");
  EXPECT_EQ(refusal("x,y,z\n1,2,3\n1,2,3\n"), "s.csv:3: the point repeats the one before it");
  EXPECT_EQ(refusal("x,y,z\n1,2,nan\n"), "s.csv:2: z 'nan': expected a finite number");
  EXPECT_EQ(refusal("x,y,z\n1,2,3\n"), "s.csv: 1 spine point(s), expected at least 2");
  EXPECT_EQ(parse_spine_csv("# spine\nx,y,z\n0,0,0\n1,0,0\n", "s.csv").cols(), 2);
}

}  // namespace
}  // namespace polarform
