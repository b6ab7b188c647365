#include "designers/cam/segment_kind.h"

#include <array>
#include <string>

#include "src/error.h"

namespace polarform {

namespace {

constexpr std::array<std::string_view, 4> kKindNames = {"dwell", "rise", "return", "rise-return"};

}  // namespace

std::string_view segment_kind_name(SegmentKind kind) {
  const auto i = static_cast<std::size_t>(kind);
  return i < kKindNames.size() ? kKindNames[i] : "unknown";
}

SegmentKind parse_segment_kind(std::string_view name) {
  for (std::size_t i = 0; i < kKindNames.size(); ++i)
    if (kKindNames[i] == name) return static_cast<SegmentKind>(i);
  throw InputError("unknown segment kind '" + std::string(name) +
                   "'; expected one of: dwell, rise, return, rise-return");
}

}  // namespace polarform
