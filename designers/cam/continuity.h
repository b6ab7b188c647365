// Continuity diagnostics of a cam program: at every segment boundary (and across 360° -> 0°) the
// one-sided values of s, v, a (and j when asked) are compared; each jump is reported with the two
// segment names, the angle and its size — never smoothed. The CLI prints them, the app highlights
// them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "designers/cam/cam_program.h"

namespace polarform {

struct ContinuityIssue {
  std::string before;  // segment ending at `angle`
  std::string after;   // segment starting at `angle`
  double angle = 0.0;  // rad, in [0, 2π)
  int derivative = 0;  // 0 displacement, 1 velocity, 2 acceleration, 3 jerk
  double before_value = 0.0;  // unit/rad^derivative
  double after_value = 0.0;
  std::string unit = "mm";  // of s: "mm", or "°" for an oscillating follower's swing
  double jump() const { return after_value - before_value; }
  // e.g. "acceleration jumps by 20 mm/rad² (0 -> 20) at 90° between 'dwell 1' and 'rise'".
  std::string message() const;
};

// Compares derivatives 0..highest_derivative (<= 3) at every boundary; a jump counts when
// |jump| > relative_tolerance * max(1, |before|, |after|). Issues are ordered by angle, then
// derivative. `unit` is the unit of s for the messages.
std::vector<ContinuityIssue> check_continuity(const CamProgram& program, int highest_derivative = 2,
                                              double relative_tolerance = 1e-9,
                                              std::string_view unit = "mm");

}  // namespace polarform
