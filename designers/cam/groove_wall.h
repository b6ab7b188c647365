// GrooveWall: one groove wall of a barrel cam as the height z = h(ψ, ρ) over the cam-frame polar
// angle ψ and the distance ρ from the cam axis. The roller's contact point for cam angle θ at
// distance t along the roller axis (BarrelCam::groove_wall_point) lies at radius
// ρ = sqrt(t² + Rr² cos² α) — slightly beyond t, by the tangential offset Rr cos α — and polar
// angle ψ = φ(θ) + atan(Rr cos α / t); h inverts both by safeguarded Newton with exact derivatives.
#pragma once

#include "designers/cam/barrel_cam.h"

namespace polarform {

struct WallPoint {
  double theta = 0.0;  // cam angle of the contact, rad
  double t = 0.0;      // distance along the roller axis, mm
  double z = 0.0;      // wall height, mm
};

class GrooveWall {
 public:
  // side = +1 (wall on the +z side of the track) or -1; InputError otherwise.
  GrooveWall(const BarrelCam& cam, int side);

  int side() const { return side_; }
  // The smallest radius at which h is single-valued in ρ: √2·Rr (then t >= Rr along the roller).
  double min_radius() const;
  // The contact on the wall at polar angle ψ (any real, cam frame) and radius ρ >= min_radius().
  // Throws NumericalError if the wall is not single-valued in ψ there (an undercut groove).
  WallPoint at(double psi, double rho) const;
  double height(double psi, double rho) const { return at(psi, rho).z; }

 private:
  // t at radius ρ for lift slope a = s'(θ): the root of t² + Rr² a² / (a² + t²) = ρ².
  double distance(double a, double rho) const;
  // ψ(θ) at radius ρ and its θ-derivative.
  void polar_angle(double theta, double rho, double* psi, double* rate) const;

  BarrelCam cam_;
  int side_;
};

}  // namespace polarform
