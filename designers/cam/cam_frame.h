// The cam's sense of rotation and the cam-fixed frame: the cam turns by θ about the origin; a
// point fixed in the world on the follower line (polar angle π/2, the +y side) is seen in the cam
// frame at polar angle φ = π/2 - σθ (σ = +1 counter-clockwise, -1 clockwise).
#pragma once

#include <numbers>

namespace polarform {

enum class Rotation { CounterClockwise, Clockwise };

inline int sense(Rotation r) { return r == Rotation::CounterClockwise ? 1 : -1; }

// Cam-frame polar angle of the follower line at cam angle θ, and its inverse.
inline double follower_polar_angle(double theta, Rotation r) { return std::numbers::pi / 2 - sense(r) * theta; }
inline double cam_angle(double phi, Rotation r) { return sense(r) * (std::numbers::pi / 2 - phi); }

}  // namespace polarform
