#include "ui/studio/segment_edits.h"

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform::studio {
namespace {

// Throws unless 0 <= i < size: "no segment 7 (the cam has 4)".
void check_index(const std::vector<SegmentSpec>& segments, int i) {
  if (i >= 0 && i < static_cast<int>(segments.size())) return;
  throw InputError("no segment " + std::to_string(i + 1) + " (the cam has " +
                   std::to_string(segments.size()) + ")");
}

}  // namespace

double set_boundary(std::vector<SegmentSpec>& segments, int k, double angle) {
  if (k < 1 || k >= static_cast<int>(segments.size()))
    throw InputError("no boundary " + std::to_string(k) +
                     " between two segments (the cam has " + std::to_string(segments.size()) +
                     ")");
  SegmentSpec& before = segments[k - 1];
  SegmentSpec& after = segments[k];
  const double lo = before.start + kMinSegmentWidth, hi = after.end - kMinSegmentWidth;
  if (lo > hi) return before.end;
  angle = std::clamp(angle, lo, hi);
  before.end = angle;
  after.start = angle;
  return angle;
}

int insert_dwell_after(std::vector<SegmentSpec>& segments, int i) {
  check_index(segments, i);
  SegmentSpec& s = segments[i];
  if (s.end - s.start < 2.0 * kMinSegmentWidth)
    throw InputError("segment " + std::to_string(i + 1) + " is " + degrees_text(s.end - s.start) +
                     " wide; splitting it would leave parts narrower than " +
                     degrees_text(kMinSegmentWidth));
  const double middle = 0.5 * (s.start + s.end);
  SegmentSpec dwell;
  dwell.kind = SegmentKind::Dwell;
  dwell.start = middle;
  dwell.end = s.end;
  s.end = middle;
  segments.insert(segments.begin() + i + 1, dwell);
  return i + 1;
}

void delete_segment(std::vector<SegmentSpec>& segments, int i) {
  check_index(segments, i);
  if (segments.size() < 2) throw InputError("a cam needs at least one segment");
  if (i > 0)
    segments[i - 1].end = segments[i].end;
  else
    segments[1].start = segments[0].start;
  segments.erase(segments.begin() + i);
}

int move_segment(std::vector<SegmentSpec>& segments, int i, int direction) {
  check_index(segments, i);
  if (direction != 1 && direction != -1)
    throw InputError("the direction is -1 (earlier) or +1 (later), got " +
                     std::to_string(direction));
  const int j = i + direction;
  if (j < 0 || j >= static_cast<int>(segments.size()))
    throw InputError("segment " + std::to_string(i + 1) + " is already " +
                     (j < 0 ? "first" : "last"));
  const int first = std::min(i, j);
  SegmentSpec& a = segments[first];
  SegmentSpec& b = segments[first + 1];
  const double start = a.start, width_b = b.end - b.start, end = b.end;
  std::swap(a, b);  // b's content now first
  a.start = start;
  a.end = start + width_b;
  b.start = a.end;
  b.end = end;
  return j;
}

void set_kind(SegmentSpec& segment, SegmentKind kind, double default_lift) {
  if (segment.kind == kind) return;
  if (kind == SegmentKind::Dwell)
    segment.lift = 0.0;
  else if (segment.kind == SegmentKind::Dwell)
    segment.lift = default_lift;
  segment.kind = kind;
}

}  // namespace polarform::studio
