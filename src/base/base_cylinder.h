// BaseCylinder: the unit-radius cylinder over θ ∈ [θs, θe], z ∈ [zs, ze] as a NURBS surface of
// degree (1, 2) (RQB azimuth) or (1, 4) (quartic azimuth); Bae 2002, eq. (3.7). u ↔ z with
// u = (z − zs)/(ze − zs) ∈ [0, 1], v ↔ θ through the azimuth BaseCircle (Bae 2002, §3.2).
#pragma once

#include <numbers>

#include <Eigen/Core>

#include "src/base/base_circle.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

class BaseCylinder {
 public:
  // Requires z_start < z_end (finite).
  BaseCylinder(BaseCircle azimuth, double z_start, double z_end);
  // Equal azimuth arcs of at most max_sweep (π/2: the square-based construction).
  BaseCylinder(ArcKind kind, double theta_start, double theta_end, double z_start, double z_end,
               AlphaRule rule = AlphaRule::minimax,
               ArcParametrization param = ArcParametrization::angle,
               double max_sweep = std::numbers::pi / 2);

  const NurbsSurface& surface() const { return surface_; }
  const BaseCircle& azimuth() const { return azimuth_; }
  double z_start() const { return z_start_; }
  double z_end() const { return z_end_; }

  // (u, v) of the surface point on the ray at azimuth θ and height z; Bae 2002, §3.2. z must lie
  // in [zs, ze] (within a relative 1e-12).
  Eigen::Vector2d parameters(double theta, double z) const;
  // (θ, z) of the surface point at (u, v).
  Eigen::Vector2d angles_height(double u, double v) const;

 private:
  BaseCircle azimuth_;
  double z_start_, z_end_;
  NurbsSurface surface_;
};

}  // namespace polarform
