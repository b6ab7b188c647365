#include "designers/cam/continuity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <locale>
#include <numbers>
#include <sstream>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {
namespace {

constexpr std::array<const char*, 4> kQuantity = {"displacement", "velocity", "acceleration", "jerk"};
constexpr std::array<const char*, 4> kPerRadian = {"", "/rad", "/rad²", "/rad³"};

}  // namespace

std::string ContinuityIssue::message() const {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(6);
  out << kQuantity[derivative] << " jumps by " << jump() << (unit == "°" ? "" : " ") << unit
      << kPerRadian[derivative] << " (" << before_value << " -> " << after_value << ") at "
      << degrees_text(angle) << " between '" << before << "' and '" << after << "'";
  return out.str();
}

std::vector<ContinuityIssue> check_continuity(const CamProgram& program, int highest_derivative,
                                              double relative_tolerance, std::string_view unit) {
  if (highest_derivative < 0 || highest_derivative > 3)
    throw InputError("continuity check: highest derivative " + std::to_string(highest_derivative) + " outside [0, 3]");
  const std::vector<MotionSegment>& segs = program.segments();
  std::vector<ContinuityIssue> issues;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const MotionSegment& before = segs[(i + segs.size() - 1) % segs.size()];  // segment 0 follows the last
    const MotionSegment& after = segs[i];
    double left[4], right[4];
    before.derivatives(before.end(), highest_derivative, left);
    after.derivatives(after.start(), highest_derivative, right);
    for (int k = 0; k <= highest_derivative; ++k) {
      const double scale = std::max({1.0, std::abs(left[k]), std::abs(right[k])});
      if (std::abs(right[k] - left[k]) > relative_tolerance * scale)
        issues.push_back(
            {before.name(), after.name(), after.start(), k, left[k], right[k], std::string(unit)});
    }
  }
  return issues;
}

}  // namespace polarform
