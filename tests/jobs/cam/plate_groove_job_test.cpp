// Grooved plate cams end to end: both flanks of the groove (the exported profile and the outer
// flank) measured against independent roller-centre oracles (translating_oracle.h, arm_oracle.h) by
// dense sampling — each flank at the roller radius from the roller centres, within the tolerance;
// the outer flank's undercut refused where the closed-form pitch curvature says 1 + Rr κ <= 0;
// groove_plate.igs/.stp read back through Open CASCADE; and the groove plate solid valid in Open
// CASCADE with the volume of the disc less the bore and the groove (Steiner: the groove's area is
// 2 Rr times the pitch curve's length).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <regex>

#include "jobs/cam/cam_job.h"
#include "jobs/cam/cam_outputs.h"
#include "src/units.h"
#include "tests/support/designers/arm_oracle.h"
#include "tests/support/designers/translating_oracle.h"
#include "tests/support/jobs/cam_job_support.h"
#include "tests/support/jobs/envelope_deviation.h"

#if POLARFORM_HAVE_OCCT
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "tests/support/export/occt_readback.h"
#endif

namespace polarform {
namespace {

using Eigen::Vector2d;
using namespace cam_job_test;
constexpr double pi = std::numbers::pi;

// The roller centre in the cam frame at θ, from the oracle that fits the follower.
std::function<Vector2d(double)> centre_path(const CamDesign& d) {
  if (is_oscillating(d.follower.kind)) {
    const test::ArmOracle o = test::ArmOracle::of(d);
    return [o](double t) { return Vector2d(o.to_cam(o.roller_centre(t), t)); };
  }
  const test::TranslatingOracle o = test::TranslatingOracle::of(d);
  return [o](double t) { return o.first(t); };
}

// The oscillating example with an 6 mm groove.
CamProject grooved_oscillating() {
  CamProject p = load_example("oscillating_roller");
  p.cam.groove_depth = 6;
  return p;
}

TEST(PlateGrooveJob, BothFlanksAreAtTheRollerRadiusFromTheRollerCentres) {
  for (const CamProject& p : {load_example("grooved"), grooved_oscillating()}) {
    SCOPED_TRACE(follower_kind_name(p.cam.follower.kind));
    const CamJobResult r = run_cam_job(p);
    ASSERT_TRUE(r.conversion.companion);
    const CompanionCurve& outer = *r.conversion.companion;
    EXPECT_EQ(outer.kind, CompanionKind::GrooveOuterFlank);
    const double tol = p.conversion.tolerance, rr = p.cam.follower.roller_radius;
    const auto path = centre_path(p.cam);
    const test::Deviation inner_dev =
        test::envelope_deviation(path, rr, test::dense_points(plate_profile(r).curve, 40000));
    const test::Deviation outer_dev =
        test::envelope_deviation(path, rr, test::dense_points(outer.conversion.curve, 40000));
    EXPECT_LE(inner_dev.worst(), tol);
    EXPECT_LE(outer_dev.worst(), tol);
    // The converter's own dense measure agrees with the oracle's to the sampling's resolution.
    EXPECT_LE(outer.conversion.max_normal_error, tol);
    EXPECT_NEAR(outer_dev.worst(), outer.conversion.max_normal_error, 0.25 * tol);
    EXPECT_LE(*std::max_element(outer.error.error.begin(), outer.error.error.end()), tol);
    // The outer flank lies on the far side of the pitch curve: beyond the prime circle.
    double least_outer = 1e300;
    for (const Vector2d& x : test::dense_points(outer.conversion.curve, 2000))
      least_outer = std::min(least_outer, x.norm());
    EXPECT_NEAR(least_outer, p.cam.base_radius + 2 * rr, tol);
    RecordProperty(std::string(follower_kind_name(p.cam.follower.kind)) + " outer flank error",
                   std::to_string(outer_dev.worst()));
  }
}

// Pitch curve r(θ) = Rp + s(θ) of a radial roller follower in polar form: its curvature from the
// closed form κ = (r² + 2r'² − r r'')/(r² + r'²)^{3/2} (DESIGN.md §4.4).
double pitch_curvature(const CamProgram& s, double rp, double theta) {
  double d[3];
  s.derivatives(theta, 2, d);
  const double r = rp + d[0], r1 = d[1], r2 = d[2];
  return (r * r + 2 * r1 * r1 - r * r2) / std::pow(r * r + r1 * r1, 1.5);
}

TEST(PlateGrooveJob, AnOuterFlankUndercutIsAnErrorWhereThePitchCurveTurnsTooTightly) {
  // A 60 mm rise over 40° from a 30 mm base circle: the pitch curve is concave at the start of
  // the rise with a radius of curvature below the 10 mm roller's (and convex at its end with a
  // radius above it: the inner flank is fine).
  CamProject p = load_example("grooved");
  p.cam.base_radius = 30;
  p.cam.segments[0].end = p.cam.segments[1].start = 40 * kRadiansPerDegree;
  p.cam.segments[0].lift = p.cam.segments[2].lift = 60;
  std::string message = "accepted";
  try {
    run_cam_job(p);
  } catch (const InfeasibleCamError& e) {
    FAIL() << "the inner flank should be fine: " << e.what();
  } catch (const InputError& e) {
    message = e.what();
  }
  const std::smatch m = [&] {
    std::smatch match;
    std::regex_search(message, match,
                      std::regex("cam groove outer flank is not single-valued in polar angle "
                                 "between θ = ([0-9.]+)° and ([0-9.]+)°"));
    return match;
  }();
  ASSERT_EQ(m.size(), 3u) << message;
  RecordProperty("message", message);
  EXPECT_NE(message.find("reduce the roller radius"), std::string::npos) << message;
  const double from = std::stod(m[1]) * kRadiansPerDegree, to = std::stod(m[2]) * kRadiansPerDegree;
  const CamProgram program = make_program(p.cam);
  const double rp = p.cam.base_radius + p.cam.follower.roller_radius,
               rr = p.cam.follower.roller_radius;
  // The closed form: 1 + Rr κ <= 0 inside the reported range, > 0 on the dwell.
  EXPECT_LE(1 + rr * pitch_curvature(program, rp, 0.5 * (from + to)), 0.0);
  EXPECT_GT(1 + rr * pitch_curvature(program, rp, 2 * pi - 1e-3), 0.0);
}

TEST(PlateGrooveJob, AGrooveNeedsARoller) {
  for (FollowerKind kind : {FollowerKind::KnifeEdge, FollowerKind::FlatFaced}) {
    CamDesign d = load_example("grooved").cam;
    d.follower.kind = kind;
    try {
      make_plate_cam(d);
      ADD_FAILURE() << "accepted a groove on " << follower_kind_name(kind);
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("groove-depth: a grooved plate cam needs a roller", 0),
                0u)
          << e.what();
    }
  }
}

#if POLARFORM_HAVE_OCCT

// The edges Open CASCADE makes of a flank file (a curve may come split at its arc junctions),
// sampled densely and sorted by flank: inner where an edge's middle point lies nearer the cam
// centre than the roller centre nearest to it, in the file's order.
std::array<std::vector<Vector2d>, 2> occt_flanks(const TopoDS_Shape& shape,
                                                 const std::function<Vector2d(double)>& path) {
  std::array<std::vector<Vector2d>, 2> out;
  for (const std::vector<Vector2d>& edge : exchange_test::sampled_edges(shape, 40000)) {
    const Vector2d x = edge[edge.size() / 2];
    Vector2d nearest = path(0);
    for (int i = 1; i < 3600; ++i)
      if ((x - path(2 * pi * i / 3600)).norm() < (x - nearest).norm())
        nearest = path(2 * pi * i / 3600);
    std::vector<Vector2d>& flank = out[x.norm() < nearest.norm() ? 0 : 1];
    flank.insert(flank.end(), edge.begin(), edge.end());
  }
  return out;
}

TEST(PlateGrooveOcct, GroovePlateFilesCarryBothFlanksWithinTheTolerance) {
  const ExampleRun& run = example("grooved");
  const CamDesign& d = run.result.project().cam;
  const double tol = run.result.project().conversion.tolerance;
  const auto path = centre_path(d);
  for (const char* file : {"groove_plate.igs", "groove_plate.stp"}) {
    SCOPED_TRACE(file);
    const TopoDS_Shape shape = exchange_test::read_exchange_file(run.dir / file);
    for (const std::vector<Vector2d>& flank : occt_flanks(shape, path)) {
      ASSERT_GT(flank.size(),
                5000u);  // one edge per flank since the knot removal: half the samples each
      EXPECT_LE(test::envelope_deviation(path, d.follower.roller_radius, flank).worst(), tol);
    }
  }
}

TEST(PlateGrooveOcct, TheGroovePlateIsOneValidSolidWithTheGroovesVolume) {
  const ExampleRun& run = example("grooved");
  const CamDesign& d = run.result.project().cam;
  const double thickness = 20, bore = 20, rr = d.follower.roller_radius;
  CamOutputOptions options;
  options.solid_thickness = thickness;
  options.bore_diameter = bore;
  const ScratchDir dir("groove_solid");
  write_cam_outputs(run.result, dir.path(), options);
  const TopoDS_Shape shape = exchange_test::read_exchange_file(dir / "cam_solid.stp");
  TopTools_IndexedMapOfShape solids, faces;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  EXPECT_EQ(solids.Extent(), 1);
  // Rim, bottom, top ring, island, both flank walls, floor, bore.
  EXPECT_EQ(faces.Extent(), 8);
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
  // The pitch curve's length and largest radius from the oracle; the disc reaches Rr beyond the
  // outer flank, whose largest radius is the pitch curve's + Rr.
  const auto path = centre_path(d);
  double length = 0, reach = 0;
  constexpr int n = 200000;
  for (int i = 0; i < n; ++i) {
    length += (path(2 * pi * (i + 1) / n) - path(2 * pi * i / n)).norm();
    reach = std::max(reach, path(2 * pi * i / n).norm());
  }
  const double disc = reach + 2 * rr;
  const double exact =
      pi * (disc * disc - bore * bore / 4) * thickness - 2 * rr * length * d.groove_depth;
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props, 1e-9);
  // The exported flanks are within ε of the exact ones, and so is the disc's radius (taken from
  // the outer flank): the volume is within ε times the disc's rim area and both walls' areas.
  const double tol = run.result.project().conversion.tolerance;
  const double bound = tol * (2 * pi * disc * thickness + 2 * length * d.groove_depth);
  EXPECT_LT(std::abs(props.Mass() - exact), bound) << props.Mass() << " vs " << exact;
  RecordProperty("relative volume error", std::to_string(std::abs(props.Mass() - exact) / exact));
}

#else

TEST(PlateGrooveOcct, Skipped) {
  GTEST_SKIP() << "Open CASCADE not found at configure time: groove read-back not tested";
}

#endif

}  // namespace
}  // namespace polarform
