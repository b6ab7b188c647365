// The kinds of cam program segment and their project-file names: a dwell, a rise, a return, and a
// rise–return (the follower rises by the lift and comes back within one segment, without a dwell
// at the top; Norton, Handbook, single-dwell functions).
#pragma once

#include <string_view>

namespace polarform {

enum class SegmentKind { Dwell, Rise, Return, RiseReturn };

std::string_view segment_kind_name(SegmentKind kind);  // "dwell", "rise", "return", "rise-return"
// Throws InputError naming the unknown kind and listing the valid names.
SegmentKind parse_segment_kind(std::string_view name);

}  // namespace polarform
