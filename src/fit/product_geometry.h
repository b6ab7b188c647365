// The fitted geometry S = F·B evaluated through its factors: the single-valued function F and the
// base circle(s), without forming the high-degree NURBS product (Bae 2002, eqs. (2.1), (3.5),
// (3.8)); the symbolic product is the same surface exactly. It gives points and first partials
// without allocating, and the foot point (closest point) of a data point by Gauss–Newton from its
// synchronized parameters, which is how the fitters measure TRUE point-to-geometry distances.
#pragma once

#include <Eigen/Core>

#include "src/nurbs/bspline_surface.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

class BaseCircle;
class BaseCylinder;
class BaseSphere;

struct FootPoint {
  double u = 0.0, v = 0.0;
  double distance = 0.0;  // signed: positive on the side away from the centre / axis
  bool converged = false;
};

class ProductGeometry {
 public:
  // C(v) = F(v)·B(v) in the local xy plane (F a 1 x n surface of degree 0 in u).
  static ProductGeometry polar(const BSplineSurface& F, const BaseCircle& base);
  // S(u, v) = F(u, v)·B(u, v), B the base sphere (u ↔ φ, v ↔ θ); Bae 2002, eq. (B.2).
  static ProductGeometry spherical(const BSplineSurface& F, const BaseSphere& base);
  // S(u, v) = (F·X, F·Y, Z), B the base cylinder (u ↔ z, v ↔ θ); Bae 2002, eq. (B.3).
  static ProductGeometry cylindrical(const BSplineSurface& F, const BaseCylinder& base);

  // S, S_u, S_v at (u, v) in local coordinates (polar: z = 0 and S_u = 0).
  void evaluate(double u, double v, double* S, double* Su, double* Sv) const;
  Eigen::Vector3d point(double u, double v) const;
  // The scalar F(u, v).
  double function(double u, double v) const;

  // The closest point of the geometry to P (local coordinates) near the start parameters:
  // Gauss–Newton on |S − P|² with the parameters clamped to the domain (wrapped around a closed
  // v). The last step is taken in the tangent-plane model; it stops when that model's distance
  // error, about κ·step²/2, is below 1e-10 of the distance for curvatures κ ~ 1/|S| (or the step
  // is below 1e-13·|S|); at most 30 iterations.
  FootPoint foot_point(const Eigen::Vector3d& P, double u, double v) const;

  bool closed_v() const { return closed_v_; }
  double front_u() const { return u0_; }
  double back_u() const { return u1_; }
  double front_v() const { return v0_; }
  double back_v() const { return v1_; }

 private:
  enum class Kind { polar, spherical, cylindrical };
  ProductGeometry(Kind kind, const BSplineSurface& F, const NurbsCurve2d* meridian,
                  const NurbsCurve2d& azimuth, bool closed_v, double z0, double z1);

  Kind kind_;
  const BSplineSurface* F_;
  const NurbsCurve2d* meridian_;  // spherical only: (cos φ, sin φ) read as (z, r)
  const NurbsCurve2d* azimuth_;
  bool closed_v_;
  double z0_, z1_;                // cylindrical height range (u = 0 .. 1)
  double u0_, u1_, v0_, v1_;
};

// A planar rational B-spline (homogeneous BSpline of dim 3) and its first derivative at u, written
// as out = (x, y, x', y') without allocating; NURBS Book A4.2 (first order).
void rational_point_and_derivative(const BSpline& homogeneous, double u, double* out);

}  // namespace polarform
