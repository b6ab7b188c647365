// BaseSphere: the unit sphere over [φs, φe] × [θs, θe] (φ polar angle from +z, θ azimuth) as the
// surface of revolution of a meridian BaseCircle (u ↔ φ) about z, swept by an azimuth BaseCircle
// (v ↔ θ); Bae 2002, eq. (3.3), NURBS Book A8.1. Its synchronization (φ, θ) ↔ (u, v) is the base
// of spherical surface fitting (Bae 2002, §3.1 Step 3).
#pragma once

#include <numbers>

#include <Eigen/Core>

#include "src/base/base_circle.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

class BaseSphere {
 public:
  // The meridian's breakpoints are polar angles in [0, π]; the azimuth circle may be closed.
  BaseSphere(BaseCircle meridian, BaseCircle azimuth);
  // Equal arcs of at most max_sweep in each direction (π/2: up to 2 x 4 patches, Bae (3.3)).
  BaseSphere(ArcKind kind, double phi_start, double phi_end, double theta_start, double theta_end,
             AlphaRule rule = AlphaRule::minimax,
             ArcParametrization param = ArcParametrization::angle,
             double max_sweep = std::numbers::pi / 2);

  const NurbsSurface& surface() const { return surface_; }
  const BaseCircle& meridian() const { return meridian_; }
  const BaseCircle& azimuth() const { return azimuth_; }

  // (u, v) of the surface point on the ray at polar angle φ and azimuth θ; Bae 2002, §3.1 Step 3
  // (v from θ on the azimuth circle, u from φ on the meridian, both by (2.7)–(2.8)).
  Eigen::Vector2d parameters(double phi, double theta) const;
  // (φ, θ) of the surface point at (u, v).
  Eigen::Vector2d angles(double u, double v) const;

 private:
  BaseCircle meridian_, azimuth_;
  NurbsSurface surface_;
};

}  // namespace polarform
