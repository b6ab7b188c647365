// Control points against the peers (issue 14): for every plate cam of examples/cams and every
// synthesised head of examples/vessels, and five cams and three heads that are not examples
// (other laws, followers and head shapes: other_cams, other_heads), at ε = 1e-2, 1e-3, 1e-4 mm, the
// exact-form profile, the degree-3 profile (knots by need, degree_limited.h), Open CASCADE's
// GeomAPI_PointsToBSpline (degree 3, and degrees 3..8) and SISL's s1961 (degree 3, and the best of
// degrees 3..8) fitted to dense contour samples, every curve measured by the tests' own dense
// distance to the exact contour (ours must meet ε).
// Always on: the degree-3 profile has no more control points than the best cubic peer (OCCT's or
// SISL's degree-3 result), and the exact form (the product C = F·B refitted, compaction="refit") no
// more than the best peer fit (OCCT's or SISL's, any degree), as recorded below, but for the known
// misses listed with their bounds (Open CASCADE's fits take about a second each, too slow for every
// run).
// On request (POLARFORM_PEER_TABLE=1, 10 minutes on a busy 2-core machine): the same against both
// peers fitted live, the table printed and recorded; a peer's time is in parentheses with its
// measured distance. POLARFORM_PEER_TABLE=sisl fits SISL only (6.5 minutes there).
// Degree 3, ours / OCCT deg 3 at ε = 1e-2, 1e-3, 1e-4 (before: uniform knots in ψ; after: knots by
// need, sliding minimax fit):
//                                             before                     after
//   roller                                    37/31   63/51   165/87   17/31   26/51   48/87
//   flat_faced                                46/33   76/69   141/126  15/33   23/69   40/126
//   offset_roller                             46/33   148/106 390/310  18/33   30/106  48/310
//   polynomial                                33/25   60/50   124/86   18/25   26/50   47/86
//   scca_dynamics                             37/29   69/58   148/111  17/29   25/58   43/111
//   oscillating_roller                        40/34   81/67   147/139  17/34   29/67   50/139
//   oscillating_flat_faced                    137/84  197/197 549/451  17/84   33/197  51/451
//   grooved                                   32/26   54/42   114/72   17/26   27/42   47/72
//   conjugate (grooved's)                     32/26   54/42   114/72   17/26   27/42   47/72
//   hemispherical                             13/13   21/20   35/33    10/13   17/20   31/33
//   ellipsoidal_2_1                           38/32   58/64   104/114  17/32   28/64   50/114
//   torispherical_100_6                       116/84  195/173 338/285  25/84   46/173  82/285
//   custom_curvature                          30/30   51/48   87/81    20/30   34/48   60/81
//   (both examples now choose their smoothing, smoothing="auto": new contours, OCCT re-recorded
//   live: torispherical_100_6 20/64 35/146 59/236, custom_curvature 12/20 23/37 41/62)
//   minimum_stress_2_1_depth                  38/33   64/61   112/105  16/33   31/61   51/105
//   harmonic_modified_sine_roller             —       —       —        16/28   25/106  44/325
//   modified_trapezoid_345_flat               —       —       —        13/28   23/61   41/111
//   constant_acceleration_cubic_offset_roller —       —       —        18/43   31/177  50/437
//   cycloidal_harmonic_flat                   —       —       —        15/58   29/136  49/306
//   345_no_dwell_roller                       —       —       —        12/17   21/31   36/43
//   ellipsoidal_3_1                           —       —       —        19/58   29/116  54/208
//   torispherical_80_10                       —       —       —        22/61   40/112  72/203
//   ellipsoidal_1.5_1_degree_4                —       —       —        14/20   24/41   40/67
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>

#include "designers/cam/cam_design.h"
#include "designers/convert/degree_limited.h"
#include "designers/convert/occt_peer.h"
#include "designers/convert/polar_conversion.h"
#include "designers/convert/sisl_peer.h"
#include "jobs/cam/cam_job.h"
#include "jobs/project/vessel_project.h"
#include "jobs/vessel/vessel_job.h"
#include "src/units.h"
#include "tests/support/designers/contour_distance.h"
#include "tests/support/jobs/cam_job_support.h"
#include "tests/support/jobs/vessel_job_support.h"

namespace polarform {
namespace {

struct Contour {
  std::string name;
  PolarFunction R;
};

// Plate cams not among the examples: other laws (harmonic and constant-acceleration with their
// acceleration jumps, modified sine and trapezoid, 3-4-5, cubic), followers and sizes.
std::vector<Contour> other_cams() {
  const auto segment = [](SegmentKind kind, double from, double to, double lift, MotionLaw law) {
    SegmentSpec s;
    s.kind = kind, s.start = from * kRadiansPerDegree, s.end = to * kRadiansPerDegree;
    s.lift = lift, s.law = law;
    return s;
  };
  using K = SegmentKind;
  using L = MotionLaw;
  const auto dwell = [&](double from, double to) {
    return segment(K::Dwell, from, to, 0, L::Cycloidal);
  };
  std::vector<std::pair<std::string, CamDesign>> designs(5);
  designs[0].first = "harmonic_modified_sine_roller";
  designs[0].second.follower = {FollowerKind::Roller, 0.0, 8.0};
  designs[0].second.base_radius = 30;
  designs[0].second.segments = {segment(K::Rise, 0, 120, 15, L::SimpleHarmonic), dwell(120, 180),
                                segment(K::Return, 180, 300, 15, L::ModifiedSine), dwell(300, 360)};
  designs[1].first = "modified_trapezoid_345_flat";
  designs[1].second.follower = {FollowerKind::FlatFaced, 0.0, 0.0};
  designs[1].second.base_radius = 50;
  designs[1].second.segments = {segment(K::Rise, 0, 100, 10, L::ModifiedTrapezoid), dwell(100, 160),
                                segment(K::Return, 160, 280, 10, L::Polynomial345),
                                dwell(280, 360)};
  designs[2].first = "constant_acceleration_cubic_offset_roller";
  designs[2].second.follower = {FollowerKind::Roller, 5.0, 12.0};
  designs[2].second.base_radius = 35;
  designs[2].second.segments = {
      dwell(0, 30), segment(K::Rise, 30, 150, 25, L::ConstantAcceleration), dwell(150, 200),
      segment(K::Return, 200, 330, 25, L::Cubic), dwell(330, 360)};
  designs[3].first = "cycloidal_harmonic_flat";
  designs[3].second.follower = {FollowerKind::FlatFaced, 0.0, 0.0};
  designs[3].second.base_radius = 60;
  designs[3].second.segments = {segment(K::Rise, 0, 60, 8, L::Cycloidal),
                                segment(K::Return, 60, 150, 8, L::SimpleHarmonic), dwell(150, 360)};
  designs[4].first = "345_no_dwell_roller";
  designs[4].second.follower = {FollowerKind::Roller, 0.0, 5.0};
  designs[4].second.base_radius = 25;
  designs[4].second.segments = {segment(K::Rise, 0, 180, 12, L::Polynomial345),
                                segment(K::Return, 180, 360, 12, L::Polynomial345)};
  std::vector<Contour> out;
  for (const auto& [name, design] : designs) out.push_back({name, cam_profile_function(design)});
  return out;
}

// Heads not among the examples: an ellipsoidal 3:1, a torispherical with crown 0.8 D and knuckle
// 0.1 D, an ellipsoidal 1.5:1 synthesised at degree 4.
std::vector<Contour> other_heads() {
  const auto xml = [](double radius, const std::string& head, double ddr, int degree,
                      int ordinates) {
    const std::string r = std::to_string(radius), d = std::to_string(ddr);
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<polarform version=\"1\">\n"
           "  <vessel radius=\"" +
           r +
           "\" length=\"1500\" thickness=\"10\" pressure=\"2\">\n"
           "    " +
           head +
           "\n"
           "    <end at=\"A\" r=\"" +
           r + "\" dr=\"0\" ddr=\"" + d +
           "\"/>\n"
           "    <end at=\"B\" r=\"" +
           r + "\" dr=\"0\" ddr=\"" + d +
           "\"/>\n"
           "    <synthesis degree=\"" +
           std::to_string(degree) + "\" ordinates=\"" + std::to_string(ordinates) +
           "\" smoothing=\"1e-6\" symmetric=\"true\"/>\n"
           "  </vessel>\n  <conversion tolerance=\"0.001\"/>\n</polarform>\n";
  };
  // R'' = R − κR² at the junction, κ the head's curvature there.
  const std::vector<std::pair<std::string, std::string>> heads = {
      {"ellipsoidal_3_1",
       xml(500, "<head preset=\"ellipsoidal\" ratio=\"3\" targets=\"48\"/>", -4000, 5, 24)},
      {"torispherical_80_10",
       xml(500, "<head preset=\"torispherical\" crown=\"800\" knuckle=\"100\" targets=\"180\"/>",
           -2000, 5, 40)},
      {"ellipsoidal_1.5_1_degree_4",
       xml(400, "<head preset=\"ellipsoidal\" ratio=\"1.5\" targets=\"48\"/>", -500, 4, 16)}};
  const std::filesystem::path dir = vessel_job_test::scratch_dir("heads");
  std::vector<Contour> out;
  for (const auto& [name, text] : heads) {
    const std::filesystem::path file = dir / (name + ".xml");
    std::ofstream(file) << text;
    std::vector<std::string> warnings;
    const VesselSolveStage s = solve_vessel_head(read_vessel_project(file, warnings));
    EXPECT_TRUE(warnings.empty()) << name;
    EXPECT_FALSE(s.solution.exact) << name;
    out.push_back({name, s.solution.profile});
  }
  return out;
}

std::vector<Contour> contours() {
  std::vector<Contour> out;
  for (const std::string& name : cam_job_test::kExampleNames) {
    const CamProject p = cam_job_test::load_example(name);
    if (p.cam.type == CamType::Plate) out.push_back({name, cam_profile_function(p.cam)});
  }
  for (const std::string& file : vessel_job_test::example_names()) {
    const VesselSolveStage s = solve_vessel_head(vessel_job_test::load_example(file));
    if (!s.solution.exact) out.push_back({file.substr(0, file.size() - 4), s.solution.profile});
  }
  for (std::vector<Contour> more : {other_cams(), other_heads()})
    for (Contour& c : more) out.push_back(std::move(c));
  return out;
}

double distance(const NurbsCurve2d& c, const PolarFunction& R) {
  return test::max_contour_distance([&](double u) { return c(u); }, c.front(), c.back(), R);
}

// Open CASCADE's control points on the same contours at ε = 1e-2, 1e-3, 1e-4 mm, as
// EveryExampleAtThreeTolerances measures them (OCCT 7.6, GeomAPI_PointsToBSpline on 1441 samples,
// the smallest verified curve over its Tol3D ladder, occt_peer.h): degree 3, and the best of
// degree 3 and degrees 3..8. Fitted live again when kSisl was recorded, OCCT gave these counts or
// more (9 contours more, mostly at 10 µm: torispherical_100_6 73 / 73 against 64 / 57,
// ellipsoidal_2_1's best 21 against 13); the recorded counts are kept as the stricter bound.
struct PeerCounts {
  std::array<int, 3> degree3, best;
};
const std::map<std::string, PeerCounts> kOcct = {
    {"roller", {{31, 51, 87}, {27, 51, 63}}},
    {"flat_faced", {{33, 69, 126}, {23, 69, 126}}},
    {"offset_roller", {{33, 106, 310}, {33, 106, 310}}},
    {"polynomial", {{25, 50, 86}, {25, 50, 86}}},
    {"scca_dynamics", {{29, 58, 111}, {29, 58, 111}}},
    {"oscillating_roller", {{34, 67, 139}, {27, 51, 139}}},
    {"oscillating_flat_faced", {{84, 197, 451}, {68, 197, 315}}},
    {"grooved", {{26, 42, 72}, {23, 39, 51}}},
    {"conjugate", {{26, 42, 72}, {23, 39, 51}}},
    {"custom_curvature", {{20, 37, 62}, {20, 28, 45}}},
    {"ellipsoidal_2_1", {{32, 64, 114}, {13, 51, 69}}},
    {"torispherical_100_6", {{64, 146, 236}, {57, 87, 195}}},
    {"minimum_stress_2_1_depth", {{33, 61, 105}, {27, 39, 75}}},
    {"hemispherical", {{13, 20, 33}, {7, 7, 13}}},
    {"harmonic_modified_sine_roller", {{28, 106, 325}, {28, 93, 291}}},
    {"modified_trapezoid_345_flat", {{28, 61, 111}, {27, 58, 105}}},
    {"constant_acceleration_cubic_offset_roller", {{43, 177, 437}, {43, 165, 437}}},
    {"cycloidal_harmonic_flat", {{58, 136, 306}, {45, 123, 291}}},
    {"345_no_dwell_roller", {{17, 31, 43}, {13, 15, 27}}},
    {"ellipsoidal_3_1", {{58, 116, 208}, {15, 105, 153}}},
    {"torispherical_80_10", {{61, 112, 203}, {51, 111, 147}}},
    {"ellipsoidal_1.5_1_degree_4", {{20, 41, 67}, {15, 33, 53}}},
};

// SISL's control points on the same contours at ε = 1e-2, 1e-3, 1e-4 mm, as
// EveryExampleAtThreeTolerances measures them (SISL 4.6.0, s1961 on 1441 samples or more,
// sisl_peer.h, the smallest verified curve over its eeps ladder): degree 3, and the best of degrees
// 3..8; 0 where no fit verified.
const std::map<std::string, PeerCounts> kSisl = {
    {"roller", {{32, 44, 87}, {26, 37, 54}}},
    {"flat_faced", {{28, 48, 86}, {26, 39, 55}}},
    {"offset_roller", {{30, 55, 95}, {30, 49, 74}}},
    {"polynomial", {{26, 47, 95}, {24, 43, 53}}},
    {"scca_dynamics", {{31, 48, 86}, {30, 43, 56}}},
    {"oscillating_roller", {{34, 52, 100}, {30, 45, 57}}},
    {"oscillating_flat_faced", {{37, 55, 102}, {29, 42, 64}}},
    {"grooved", {{27, 38, 89}, {24, 38, 45}}},
    {"conjugate", {{27, 38, 89}, {24, 38, 45}}},
    {"custom_curvature", {{22, 38, 65}, {20, 25, 34}}},
    {"ellipsoidal_2_1", {{26, 50, 76}, {17, 27, 38}}},
    {"torispherical_100_6", {{34, 59, 99}, {31, 39, 63}}},
    {"minimum_stress_2_1_depth", {{31, 43, 81}, {21, 31, 45}}},
    {"hemispherical", {{13, 20, 33}, {8, 9, 10}}},
    {"harmonic_modified_sine_roller", {{34, 50, 79}, {25, 40, 48}}},
    {"modified_trapezoid_345_flat", {{26, 47, 93}, {26, 40, 59}}},
    {"constant_acceleration_cubic_offset_roller", {{27, 59, 96}, {27, 53, 55}}},
    {"cycloidal_harmonic_flat", {{31, 49, 93}, {29, 32, 43}}},
    {"345_no_dwell_roller", {{19, 37, 55}, {18, 23, 32}}},
    {"ellipsoidal_3_1", {{37, 56, 105}, {20, 30, 47}}},
    {"torispherical_80_10", {{34, 62, 112}, {28, 51, 77}}},
    {"ellipsoidal_1.5_1_degree_4", {{26, 41, 69}, {15, 27, 44}}},
};

// The fewest control points among a row's recorded peer fits (0 where none verified).
int fewest(std::initializer_list<int> counts) {
  int best = 0;
  for (int c : counts)
    if (c > 0 && (best == 0 || c < best)) best = c;
  return best;
}

int best_peer(const std::string& name, int i) {
  return fewest({kOcct.at(name).degree3[i], kOcct.at(name).best[i], kSisl.at(name).degree3[i],
                 kSisl.at(name).best[i]});
}

int best_cubic_peer(const std::string& name, int i) {
  return fewest({kOcct.at(name).degree3[i], kSisl.at(name).degree3[i]});
}

// The exact form (the product refitted, as plate cams and vessel heads export it): no more control
// points than the best peer fit, but for known misses, each held to its count (none now: the
// heads' went when a mirror-symmetric meridian became one curve whose control values are mirror
// pairs, spline_space.h, the hemisphere 8 / 8 / 12 -> 6 / 7 / 9 against the best peer's 7 / 7 / 10;
// the 3-4-5 rise-return without dwells at 1 µm, 17 against OCCT's 15, when a seam where R's third
// derivative jumps became C2 like R instead of C^(p-1), degree_limited.h: 15 at degree 5).
int exact_form_bound(const std::string& name, int i, int best) {
  static const std::map<std::pair<std::string, int>, int> known_misses = {};
  const auto miss = known_misses.find({name, i});
  return miss == known_misses.end() ? best : miss->second;
}

// The degree-3 profile: no more control points than the best cubic peer, but for known misses,
// each held to its count (none on these contours: at 10 µm SISL's degree-3 fits take 13-37
// control points and OCCT's 13-84, ours 10-23).
int degree3_bound(const std::string& name, int i, int best) {
  static const std::map<std::pair<std::string, int>, int> known_misses = {};
  const auto miss = known_misses.find({name, i});
  return miss == known_misses.end() ? best : miss->second;
}

TEST(PeerCounts, ExactFormNoMoreControlPointsThanTheBestPeer) {
  std::string table =
      "| example | ε mm | exact form | steps | OCCT best | SISL best "
      "|\n|---|---|---|---|---|---|\n";
  for (const Contour& c : contours()) {
    ASSERT_TRUE(kOcct.count(c.name)) << c.name;
    ASSERT_TRUE(kSisl.count(c.name)) << c.name;
    for (int i = 0; i < 3; ++i) {
      const double eps = std::pow(10.0, -2 - i);
      SCOPED_TRACE(c.name + " at " + std::to_string(eps));
      ConversionOptions options;
      options.tolerance = eps;
      const PolarConversion exact = convert_polar_function(c.R, options);
      EXPECT_LE(exact.max_radial_error, eps);
      EXPECT_LE(distance(exact.curve, c.R), eps);
      ASSERT_EQ(exact.steps.size(), 2u);
      EXPECT_EQ(exact.steps[1].name, "refit");
      EXPECT_LE(exact.curve.size(), exact_form_bound(c.name, i, best_peer(c.name, i)));
      char row[256];
      std::snprintf(row, sizeof row, "| %s | %g | %d (degree %d) | %d → %d | %d | %d |\n",
                    c.name.c_str(), eps, exact.curve.size(), exact.curve.degree(),
                    exact.steps[0].control_points, exact.steps[1].control_points,
                    kOcct.at(c.name).best[i], kSisl.at(c.name).best[i]);
      table += row;
    }
  }
  std::printf("%s", table.c_str());
  RecordProperty("table", table);
}

// Always on: the degree-3 profile of every example at the three tolerances has no more control
// points than the best cubic peer's recorded result (OCCT's or SISL's), and meets ε by the tests'
// own dense measurement.
TEST(PeerCounts, DegreeThreeNoMoreControlPointsThanTheBestCubicPeer) {
  std::string table =
      "| example | ε mm | degree 3 | OCCT deg 3 | SISL deg 3 | ms |\n|---|---|---|---|---|---|\n";
  for (const Contour& c : contours()) {
    ASSERT_TRUE(kOcct.count(c.name)) << c.name;
    ASSERT_TRUE(kSisl.count(c.name)) << c.name;
    for (int i = 0; i < 3; ++i) {
      const double eps = std::pow(10.0, -2 - i);
      SCOPED_TRACE(c.name + " at " + std::to_string(eps));
      const auto start = std::chrono::steady_clock::now();
      const LimitedCurve cubic = approximate_polar_curve(c.R, 3, eps);
      const std::chrono::duration<double, std::milli> took =
          std::chrono::steady_clock::now() - start;
      EXPECT_EQ(cubic.curve.degree(), 3);
      EXPECT_LE(cubic.max_radial_error, eps);
      EXPECT_LE(distance(cubic.curve, c.R), eps);
      EXPECT_LE(cubic.control_points, degree3_bound(c.name, i, best_cubic_peer(c.name, i)));
      char row[256];
      std::snprintf(row, sizeof row, "| %s | %g | %d | %d | %d | %.1f |\n", c.name.c_str(), eps,
                    cubic.control_points, kOcct.at(c.name).degree3[i], kSisl.at(c.name).degree3[i],
                    took.count());
      table += row;
    }
  }
  std::printf("%s", table.c_str());
  RecordProperty("table", table);
}

// The full table takes minutes (Open CASCADE's fits take seconds each): run on request with
// POLARFORM_PEER_TABLE=1 (or =sisl for SISL alone). Asserts the peers' curves within ε by the
// tests' own measurement and ours against the live results, with the known misses; prints SISL's
// counts as kSisl's rows.
TEST(PeerCounts, EveryExampleAtThreeTolerances) {
  const char* mode = std::getenv("POLARFORM_PEER_TABLE");
  if (!mode) GTEST_SKIP() << "set POLARFORM_PEER_TABLE=1 (or sisl) to run";
  const bool occt = std::string(mode) != "sisl";
  std::string table =
      "| example | ε mm | exact form | degree 3 | OCCT deg 3 | OCCT deg 3..8 | SISL deg 3 | SISL "
      "best of 3..8 |\n|---|---|---|---|---|---|---|---|\n";
  std::string sisl_rows;
  for (const Contour& c : contours()) {
    PeerCounts sisl_counts{};
    for (int i = 0; i < 3; ++i) {
      const double eps = std::pow(10.0, -2 - i);
      SCOPED_TRACE(c.name + " at " + std::to_string(eps));
      ConversionOptions options;
      options.tolerance = eps;
      const PolarConversion exact = convert_polar_function(c.R, options);
      const LimitedCurve cubic = approximate_polar_curve(c.R, 3, eps);
      const double d_exact = distance(exact.curve, c.R), d_cubic = distance(cubic.curve, c.R);
      EXPECT_LE(d_exact, eps);
      EXPECT_LE(d_cubic, eps);
      char row[256];
      std::snprintf(row, sizeof row, "| %s | %g | %d (%.2g) | %d (%.2g) |", c.name.c_str(), eps,
                    exact.curve.size(), d_exact, cubic.control_points, d_cubic);
      table += row;
      std::vector<int> all, cubics;
      const auto peer_cell = [&](const PeerCurve& f, double seconds, bool is_cubic) {
        if (f.found) {
          EXPECT_LE(distance(f.curve, c.R), eps);
          all.push_back(f.control_points);
          if (is_cubic) cubics.push_back(f.control_points);
        }
        std::snprintf(row, sizeof row, " %d (%.2g, %.2f s) |", f.control_points, f.max_radial_error,
                      seconds);
        table += row;
      };
      const auto timed = [](const auto& fit) {
        const auto start = std::chrono::steady_clock::now();
        PeerCurve f = fit();
        return std::make_pair(
            std::move(f),
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      };
#if POLARFORM_HAVE_OCCT
      for (int deg_max : {3, 8}) {
        if (!occt) {
          table += " |";
          continue;
        }
        const auto [f, s] = timed([&] { return occt_points_to_bspline(c.R, 3, deg_max, eps); });
        peer_cell(f, s, deg_max == 3);
      }
#else
      table += " | |";
#endif
#if POLARFORM_HAVE_SISL
      const auto [f3, s3] = timed([&] { return sisl_s1961(c.R, 3, eps); });
      peer_cell(f3, s3, true);
      const auto [fb, sb] = timed([&] { return sisl_s1961_best(c.R, 3, 8, eps); });
      peer_cell(fb, sb, false);
      sisl_counts.degree3[i] = f3.control_points;
      sisl_counts.best[i] = fb.control_points;
#else
      table += " | |";
#endif
      int best = 0, best_cubic = 0;
      for (int n : all) best = best == 0 ? n : std::min(best, n);
      for (int n : cubics) best_cubic = best_cubic == 0 ? n : std::min(best_cubic, n);
      if (best > 0) {
        EXPECT_LE(exact.curve.size(), exact_form_bound(c.name, i, best));
      }
      if (best_cubic > 0) {
        EXPECT_LE(cubic.control_points, degree3_bound(c.name, i, best_cubic));
      }
      table += "\n";
    }
    char line[256];
    std::snprintf(line, sizeof line, "    {\"%s\", {{%d, %d, %d}, {%d, %d, %d}}},\n",
                  c.name.c_str(), sisl_counts.degree3[0], sisl_counts.degree3[1],
                  sisl_counts.degree3[2], sisl_counts.best[0], sisl_counts.best[1],
                  sisl_counts.best[2]);
    sisl_rows += line;
  }
  std::printf("%s", table.c_str());
  std::printf("kSisl:\n%s", sisl_rows.c_str());
  RecordProperty("table", table);
}

}  // namespace
}  // namespace polarform
