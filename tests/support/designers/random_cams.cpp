#include "tests/support/designers/random_cams.h"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "designers/cam/cam_analysis.h"
#include "designers/cam/contour_polar_function.h"
#include "src/error.h"

namespace polarform::test {

namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr MotionLaw kLaws[] = {MotionLaw::SimpleHarmonic,    MotionLaw::Cycloidal,
                               MotionLaw::ModifiedTrapezoid, MotionLaw::ModifiedSine,
                               MotionLaw::Polynomial345,     MotionLaw::Polynomial4567};

// Levels the motions reach in turn, back to 0: one rise and return, or rise, return part way,
// rise again, return.
std::vector<double> random_levels(std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  if (U(rng) < 0.5) return {6 + 14 * U(rng), 0.0};
  const double a = 10 + 10 * U(rng), b = 3 + (a - 9) * U(rng), c = b + 6 + 8 * U(rng);
  return {a, b, c, 0.0};
}

// True when the cam is a usable scan subject: no undercut, a single-valued contour about the
// centre and pressure angles within 40°.
bool usable(const CamDesign& d) {
  try {
    const PlateCam cam = make_plate_cam(d);
    cam_polar_function(cam);
    std::vector<double> theta;
    for (int i = 0; i < 720; ++i) theta.push_back(i * 0.5 * kDeg);
    const CamAnalysis a = analyse(cam, theta);
    return a.undercut.empty() && a.min_contour_speed.value > 0 &&
           std::abs(a.max_pressure_angle.value) < 40 * kDeg;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

CamDesign random_cam_design(std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::uniform_int_distribution<int> law(0, 5), kind(0, 2);
  for (;;) {
    CamDesign d;
    d.follower.kind = std::array{FollowerKind::KnifeEdge, FollowerKind::Roller,
                                 FollowerKind::FlatFaced}[static_cast<std::size_t>(kind(rng))];
    d.follower.roller_radius = d.follower.kind == FollowerKind::Roller ? 8 + 7 * U(rng) : 0.0;
    d.follower.offset =
        d.follower.kind != FollowerKind::FlatFaced && U(rng) < 0.5 ? 10 * U(rng) - 5 : 0.0;
    d.base_radius = 35 + 20 * U(rng);
    d.rotation = U(rng) < 0.5 ? Rotation::CounterClockwise : Rotation::Clockwise;
    const std::vector<double> levels = random_levels(rng);
    std::vector<double> spans;
    double used = 0.0;
    for (std::size_t i = 0; i < levels.size(); ++i)
      spans.push_back(50 + 60 * U(rng)), used += spans.back();
    const double dwell_total = 360 - used - 12.0 * static_cast<double>(levels.size());
    if (dwell_total < 0) continue;
    std::vector<double> share;
    double share_sum = 0.0;
    for (std::size_t i = 0; i < levels.size(); ++i)
      share.push_back(U(rng)), share_sum += share.back();
    double at = 0.0, level = 0.0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const double dwell = 12 + dwell_total * share[i] / share_sum;
      SegmentSpec rest;
      rest.kind = SegmentKind::Dwell;
      rest.start = at * kDeg;
      rest.end = (at + dwell) * kDeg;
      d.segments.push_back(rest);
      at += dwell;
      SegmentSpec m;
      m.kind = levels[i] > level ? SegmentKind::Rise : SegmentKind::Return;
      m.lift = std::abs(levels[i] - level);
      m.law = kLaws[law(rng)];
      m.start = at * kDeg;
      at = i + 1 == levels.size() ? 360.0 : at + spans[i];
      m.end = at * kDeg;
      d.segments.push_back(m);
      level = levels[i];
    }
    if (usable(d)) return d;
  }
}

}  // namespace polarform::test
