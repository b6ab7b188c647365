// Units at the edges. polarform computes in millimetres, radians and seconds; files, plots and
// screens show degrees, micrometres, metres per second squared and revolutions per minute. These
// are the named conversions, so that no file defines its own (180/π in one place, π/180 in
// another).
#pragma once

#include <cmath>
#include <numbers>

namespace polarform {

inline constexpr double kDegreesPerRadian = 180 / std::numbers::pi;
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180;
inline constexpr double kMicrometresPerMillimetre = 1e3;
inline constexpr double kMetresPerMillimetre = 1e-3;

constexpr double to_degrees(double radians) { return radians * kDegreesPerRadian; }
constexpr double to_radians(double degrees) { return degrees * kRadiansPerDegree; }
constexpr double to_micrometres(double millimetres) {
  return millimetres * kMicrometresPerMillimetre;
}

// An angle in degrees within [0, 360): where on the turn a polar angle in radians lies.
inline double degrees_in_turn(double radians) {
  const double d = std::fmod(to_degrees(radians), 360.0);
  return d < 0 ? d + 360.0 : d;
}

// The same in radians, within [0, 2π).
inline double radians_in_turn(double radians) {
  const double r = std::fmod(radians, 2 * std::numbers::pi);
  return r < 0 ? r + 2 * std::numbers::pi : r;
}

// The cam's angular speed ω [rad/s] at `rpm` revolutions per minute.
constexpr double angular_speed(double rpm) { return 2 * std::numbers::pi * rpm / 60; }

}  // namespace polarform
