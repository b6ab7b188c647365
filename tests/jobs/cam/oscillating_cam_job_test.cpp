// Oscillating followers end to end: the cam job's exact NURBS profile, for the bundled examples and
// random swing-arm designs, measured against the independent arm oracle (tests/support/designers/
// arm_oracle.h) by dense sampling (envelope_deviation.h) — every point of a roller cam's profile at
// the roller radius from the roller centres, a flat-faced cam's support function equal to the
// face's height — within the tolerance; and profile.igs / profile.stp read back through Open
// CASCADE and measured the same way.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "jobs/cam/cam_job.h"
#include "jobs/cam/cam_outputs.h"
#include "jobs/project/cam_project.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/units.h"
#include "tests/support/designers/arm_oracle.h"
#include "tests/support/jobs/cam_job_support.h"
#include "tests/support/jobs/envelope_deviation.h"

#if POLARFORM_HAVE_OCCT
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>

#include "tests/support/export/occt_readback.h"
#endif

namespace polarform {
namespace {

using cam_job_test::ScratchDir;
using Eigen::Vector2d;
using test::ArmOracle;
constexpr double pi = std::numbers::pi;

ArmOracle oracle_of(const CamProject& p) { return ArmOracle::of(p.cam); }

using test::dense_points;
using test::Deviation;

// Roller: the profile against the oracle's roller centres (envelope_deviation.h). Flat face: the
// profile's support function against h(θ).
Deviation deviation(const ArmOracle& o, const std::vector<Vector2d>& profile) {
  if (o.roller)
    return test::envelope_deviation(
        [&](double t) { return Vector2d(o.to_cam(o.roller_centre(t), t)); }, o.rr, profile);
  Deviation dev;
  for (int i = 0; i < 1440; ++i) {
    const double theta = 2 * pi * i / 1440;
    const Vector2d normal = o.to_cam(o.face_normal(theta), theta);
    double support = -1e300;
    for (const Vector2d& x : profile) support = std::max(support, x.dot(normal));
    const double gap = support - o.face_height(theta);
    dev.outside = std::max(dev.outside, gap), dev.inside = std::max(dev.inside, -gap);
  }
  return dev;
}

CamProject example_project(const std::string& name) {
  std::vector<std::string> warnings;
  return read_cam_project(cam_job_test::kExamples / (name + ".xml"), warnings);
}

TEST(OscillatingCamJob, ExampleProfilesMeetTheToleranceAgainstTheArmOracle) {
  for (const std::string name : {"oscillating_roller", "oscillating_flat_faced"}) {
    SCOPED_TRACE(name);
    const CamProject p = example_project(name);
    const CamJobResult r = run_cam_job(p);
    const Deviation dev =
        deviation(oracle_of(p), dense_points(cam_job_test::plate_profile(r).curve, 40000));
    EXPECT_LE(dev.worst(), p.conversion.tolerance);
    EXPECT_LE(r.conversion.conversion.max_normal_error, p.conversion.tolerance);
    // The converter's own measure and the oracle's agree to the sampling's resolution.
    EXPECT_NEAR(dev.worst(), r.conversion.conversion.max_normal_error,
                0.25 * p.conversion.tolerance);
  }
}

// Random swing-arm cams: pivot, arm, rollers, laws, boundaries, rotation and side drawn at random
// (fixed seed); designs the analysis finds undercut are refused (InfeasibleCamError) and counted.
TEST(OscillatingCamJob, RandomDesignsMeetTheToleranceAgainstTheArmOracle) {
  std::mt19937 rng(20261205);
  const auto uniform = [&](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  const MotionLaw laws[] = {MotionLaw::SimpleHarmonic,    MotionLaw::Cycloidal,
                            MotionLaw::ModifiedTrapezoid, MotionLaw::ModifiedSine,
                            MotionLaw::Polynomial345,     MotionLaw::Polynomial4567};
  int measured = 0, refused = 0;
  for (int trial = 0; trial < 12; ++trial) {
    CamProject p;
    CamDesign& d = p.cam;
    const bool roller = trial % 3 != 2;
    d.follower.kind = roller ? FollowerKind::OscillatingRoller : FollowerKind::OscillatingFlatFaced;
    d.base_radius = uniform(30, 60);
    d.follower.roller_radius = roller ? uniform(5, 15) : 0.0;
    const double rp = d.base_radius + d.follower.roller_radius;
    d.follower.pivot_distance = uniform(1.5, 3.0) * rp;
    d.follower.arm_length = roller ? uniform(std::abs(d.follower.pivot_distance - rp) + 0.2 * rp,
                                             d.follower.pivot_distance + 0.8 * rp)
                                   : 0.0;
    d.follower.face_offset = roller ? 0.0 : uniform(-0.3, 0.3) * d.base_radius;
    d.follower.pivot_side = uniform(0, 1) < 0.5 ? 1 : -1;
    d.rotation = uniform(0, 1) < 0.5 ? Rotation::CounterClockwise : Rotation::Clockwise;
    const double lift = uniform(5, 20);
    const double b[4] = {uniform(10, 60), uniform(150, 200), uniform(210, 250), 360};
    d.segments = {SegmentSpec{}, SegmentSpec{}, SegmentSpec{}, SegmentSpec{}};
    const SegmentKind kinds[4] = {SegmentKind::Dwell, SegmentKind::Rise, SegmentKind::Dwell,
                                  SegmentKind::Return};
    for (int k = 0; k < 4; ++k) {
      d.segments[k].kind = kinds[k];
      d.segments[k].start = (k == 0 ? 0.0 : b[k - 1]) * kRadiansPerDegree;
      d.segments[k].end = b[k] * kRadiansPerDegree;
      d.segments[k].lift = kinds[k] == SegmentKind::Dwell ? 0.0 : lift;
      d.segments[k].law = laws[std::uniform_int_distribution<int>(0, 5)(rng)];
    }
    p.conversion.tolerance = trial % 2 ? 1e-3 : 1e-4;
    SCOPED_TRACE(cam_project_xml(p));
    try {
      const CamJobResult r = run_cam_job(p);
      const Deviation dev =
          deviation(oracle_of(p), dense_points(cam_job_test::plate_profile(r).curve, 40000));
      EXPECT_LE(dev.worst(), p.conversion.tolerance);
      ++measured;
    } catch (const InfeasibleCamError&) {
      ++refused;
    } catch (const InputError& e) {  // an arm that cannot swing this lift
      EXPECT_NE(std::string(e.what()).find("cannot swing the lift"), std::string::npos) << e.what();
      ++refused;
    }
  }
  EXPECT_GE(measured, 8) << refused << " refused";
  RecordProperty("measured", measured);
}

#if POLARFORM_HAVE_OCCT

TEST(OscillatingCamJob, OpenCascadeReadsProfilesWithinTheToleranceOfTheArmOracle) {
  for (const std::string name : {"oscillating_roller", "oscillating_flat_faced"}) {
    SCOPED_TRACE(name);
    const CamProject p = example_project(name);
    const CamJobResult r = run_cam_job(p);
    const ScratchDir dir("oscillating_occt_" + name);
    write_cam_outputs(r, dir.path());
    IGESControl_Reader iges;
    ASSERT_EQ(iges.ReadFile((dir / "profile.igs").c_str()), IFSelect_RetDone);
    iges.TransferRoots();
    EXPECT_EQ(exchange_test::reader_messages(iges.WS(), true), "");
    EXPECT_LE(
        deviation(oracle_of(p), exchange_test::sampled_points(iges.OneShape(), 40000)).worst(),
        p.conversion.tolerance);
    STEPControl_Reader step;
    ASSERT_EQ(step.ReadFile((dir / "profile.stp").c_str()), IFSelect_RetDone);
    step.TransferRoots();
    EXPECT_EQ(exchange_test::reader_messages(step.WS(), true), "");
    EXPECT_LE(
        deviation(oracle_of(p), exchange_test::sampled_points(step.OneShape(), 40000)).worst(),
        p.conversion.tolerance);
  }
}

#else

TEST(OscillatingCamJob, OpenCascadeSkipped) {
  GTEST_SKIP() << "Open CASCADE not found at configure time: oscillating read-back not tested";
}

#endif

}  // namespace
}  // namespace polarform
