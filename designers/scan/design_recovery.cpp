#include "designers/scan/design_recovery.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/error.h"

namespace polarform {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kSplitMargin = 1e-6;  // rad: θ = 0 this far inside a dwell splits it

// a + 2πk nearest to `near`.
double nearest_turn(double a, double near) { return a + kTwoPi * std::round((near - a) / kTwoPi); }

// The segments in order over [first start, first start + 2π) in the scan's unwrapped angles, and
// the lowest dwell level (height, mm).
std::vector<SegmentSpec> joined_segments(const RecoveredDesign& r, double& lowest) {
  const std::size_t n = r.motions.size();
  // Boundaries and levels at each anchor k: the end of motion k − 1 and the start of motion k.
  std::vector<double> arrive(n), leave(n), level(n);
  for (std::size_t k = 0; k < n; ++k) {
    const DwellRun& anchor = r.segmentation.anchors[k];
    const LawFit& before = r.motions[(k + n - 1) % n].law();
    const LawFit& after = r.motions[k].law();
    arrive[k] = nearest_turn(before.end, anchor.start);
    leave[k] = nearest_turn(after.start, anchor.end);
    level[k] = 0.5 * (before.level + before.lift + after.level);
    if (!r.segmentation.is_dwell[k] || arrive[k] >= leave[k])
      arrive[k] = leave[k] = 0.5 * (arrive[k] + leave[k]);
  }
  lowest = *std::min_element(level.begin(), level.end());
  std::vector<SegmentSpec> out;
  double at = arrive[0];
  for (std::size_t k = 0; k < n; ++k) {
    SegmentSpec dwell;
    dwell.kind = SegmentKind::Dwell;
    dwell.start = at;
    dwell.end = at + (leave[k] - arrive[k]);
    if (dwell.end > dwell.start) out.push_back(dwell), at = dwell.end;
    const std::size_t next = (k + 1) % n;
    SegmentSpec s;
    s.kind = level[next] > level[k] ? SegmentKind::Rise : SegmentKind::Return;
    s.lift = std::abs(level[next] - level[k]);
    s.law = r.motions[k].law().shape.law;
    if (s.law == MotionLaw::Scca) s.scca = r.motions[k].law().shape.scca;
    s.start = at;
    const double span = std::fmod(std::fmod(arrive[next] - leave[k], kTwoPi) + kTwoPi, kTwoPi);
    s.end = next == 0 ? arrive[0] + kTwoPi : at + span;
    if (!(s.end > s.start) || span > kTwoPi - kSplitMargin)
      throw InputError("design recovery: the fitted motions " + std::to_string(k + 1) + " and " +
                       std::to_string(next + 1) + " overlap; the scan cannot be segmented");
    out.push_back(s);
    at = s.end;
  }
  return out;
}

}  // namespace

RecoveredDesign recover_design(const ScannedCam& scan) {
  RecoveredDesign r;
  r.segmentation = segment_motion(scan);
  for (const MotionPiece& p : r.segmentation.motions)
    r.motions.push_back(identify_law(scan.samples, p, scan.displacement.noise));
  double lowest = 0.0;
  std::vector<SegmentSpec> segments = joined_segments(r, lowest);
  // The segment holding θ = 0 (mod 2π): split there if it is a dwell, else the frame starts at it.
  const double origin = segments.front().start;
  const double zero = origin + std::fmod(std::fmod(-origin, kTwoPi) + kTwoPi, kTwoPi);
  std::size_t first = 0;
  while (first + 1 < segments.size() && segments[first].end <= zero) ++first;
  SegmentSpec& holder = segments[first];
  if (holder.kind == SegmentKind::Dwell && zero - holder.start > kSplitMargin &&
      holder.end - zero > kSplitMargin) {
    SegmentSpec tail = holder;
    holder.end = zero;
    tail.start = zero;
    segments.insert(segments.begin() + static_cast<std::ptrdiff_t>(first) + 1, tail);
    ++first;
  }
  const double base = segments[first].start;
  r.phase = std::fmod(std::fmod(base, kTwoPi) + kTwoPi, kTwoPi);
  if (r.phase > kTwoPi - kSplitMargin) r.phase = 0.0;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    SegmentSpec s = segments[(first + i) % segments.size()];
    const double shift = (first + i) < segments.size() ? base : base - kTwoPi;
    s.start = i == 0 ? 0.0 : r.design.segments.back().end;
    s.end = i + 1 == segments.size() ? kTwoPi : s.end - shift;
    r.design.segments.push_back(s);
  }
  r.design.type = CamType::Plate;
  r.design.follower = scan.follower;
  r.design.rotation = scan.rotation;
  r.design.base_radius = base_radius_from_rest(scan.follower, lowest);
  r.deviation = compare_to_nominal(scan, make_plate_cam(r.design), 3600, r.phase);
  return r;
}

}  // namespace polarform
