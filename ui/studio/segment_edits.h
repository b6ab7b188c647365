// Edits of a cam's segment list that keep it covering [0, 2π] without gaps: moving a boundary,
// inserting a dwell by halving a segment, deleting a segment (a neighbour takes its span) and
// swapping neighbours (each keeps its width). The library validates the result; these only keep
// the angles consistent. An edit that cannot be made (no such segment, the only segment, a split
// below the minimum width, a move past either end) throws InputError saying why and leaves the
// segments unchanged. Small and generic: a candidate for designers/cam.
#pragma once

#include <vector>

#include "designers/cam/motion_segment.h"

namespace polarform::studio {

// Smallest segment width the edits leave, radians (0.1°).
inline constexpr double kMinSegmentWidth = 0.1 * 3.14159265358979323846 / 180.0;

// Moves the boundary between segments k-1 and k (1 <= k < size) to `angle`, clamped so both keep
// at least kMinSegmentWidth. Returns the angle used.
double set_boundary(std::vector<SegmentSpec>& segments, int k, double angle);
// Segment i keeps the first half of its span; a new dwell takes the second. Returns its index.
// Throws when either half would be narrower than kMinSegmentWidth.
int insert_dwell_after(std::vector<SegmentSpec>& segments, int i);
// Removes segment i (size > 1); the previous segment (the next, for the first) takes its span.
void delete_segment(std::vector<SegmentSpec>& segments, int i);
// Swaps segments i and i + direction (±1) in angular order, each keeping its width. Returns the
// moved segment's new index.
int move_segment(std::vector<SegmentSpec>& segments, int i, int direction);
// Changes the kind; a dwell gets lift 0, a new rise or return `default_lift` mm.
void set_kind(SegmentSpec& segment, SegmentKind kind, double default_lift);

}  // namespace polarform::studio
