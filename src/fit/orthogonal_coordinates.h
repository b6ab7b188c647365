// The orthogonal-coordinate transforms of the fitters: polar (Bae 2002, eq. (2.2)), spherical
// (eq. (3.1)) and cylindrical (eq. (3.6)) coordinates of points already in the local frame, and
// the angle ranges (2.2)/(3.2) of the data: the azimuth range is the circle minus its largest
// data-free gap (so data across θ = 0 is not split), or the full circle when that gap is small.
#pragma once

#include <Eigen/Core>

namespace polarform {

// ρ (or r), the polar angle φ ∈ [0, π] (spherical only), the azimuth θ ∈ [0, 2π) and z
// (cylindrical only), one entry per point. Throws InputError naming the first point on the axis
// (r = 0) or at the centre (ρ = 0), where the angles are undefined.
struct PolarCoordinates {
  Eigen::VectorXd r, theta;
};
struct SphericalCoordinates {
  Eigen::VectorXd rho, phi, theta;
};
struct CylindricalCoordinates {
  Eigen::VectorXd r, theta, z;
};

PolarCoordinates polar_coordinates(const Eigen::Matrix2Xd& local, int threads = 1);
SphericalCoordinates spherical_coordinates(const Eigen::Matrix3Xd& local, int threads = 1);
CylindricalCoordinates cylindrical_coordinates(const Eigen::Matrix3Xd& local, int threads = 1);

struct AzimuthRange {
  double start = 0.0, end = 0.0;  // end − start ≤ 2π; [0, 2π] when closed
  bool closed = false;
  double largest_gap = 0.0;       // radians without data
};

// The range of the angles θ ∈ [0, 2π): closed when the largest gap between circularly
// consecutive angles is at most closed_gap, else from the end of that gap to its start (+2π).
// closed_gap <= 0 selects max(10°, 10 · 2π/n). O(n) through per-bin extremes.
AzimuthRange azimuth_range(const Eigen::VectorXd& theta, double closed_gap = 0.0);

// Whether a fit closes around the axis: decided from the data, or forced.
enum class Closure { automatic, open, closed };

// azimuth_range with the decision forced: closed gives [0, 2π]; open cuts the circle at the
// largest gap even when it is small.
AzimuthRange azimuth_range(const Eigen::VectorXd& theta, Closure closure, double closed_gap = 0.0);

// Each θ moved by a multiple of 2π into [start, start + 2π).
void unwrap_angles(Eigen::VectorXd& theta, double start);

}  // namespace polarform
