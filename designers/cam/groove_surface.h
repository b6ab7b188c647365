// The groove walls of a barrel cam as exact-form NURBS surfaces within a tolerance. Each wall
// is S(u, ρ) = (ρ·B̃(u), Z(u, ρ)): B̃ a closed base circle of quasi-uniform quartic arcs (breaks
// at the track's segment boundaries, sweeps up to 180° or up to 90°, whichever meets the measured
// tolerance with the smaller control net), ρ the distance from the cam axis (the parameter v = ρ),
// Z the wall height as a B-spline function (groove_height_fit.h), combined exactly by the modified
// cylindrical product S^w = (ρ·X^w, ρ·Y^w, Z·W, W) (Bae 2002, eq. (B.3)) into one rational
// tensor-product surface.
#pragma once

#include "designers/cam/barrel_cam.h"
#include "src/base/base_circle.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct GrooveOptions {
  double inner_radius = 0.0, outer_radius = 0.0;  // ρ range of the wall, mm
  double tolerance = 1e-3;                        // bound on the measured max error, mm
  AlphaRule alpha = AlphaRule::minimax;
  double fit_share = 0.9;  // of the tolerance for Z; the x, y part is exact
};

struct GrooveSurface {
  int side = 1;          // +1: the wall on the +z side of the track
  NurbsSurface surface;  // u: base circle parameter (≈ polar angle, rad); v = ρ, mm
  BaseCircle base;
  BSplineSurface height;  // Z(u, ρ)
  double tolerance = 0.0;
  // Error budget: Z against h(angle(u), ρ) on the fit's check grid (the arcs add none), and the
  // final surface's max |z − h(ψ, ρ)| over dense samples (the largest refined by golden section)
  // at each point's own polar angle ψ and radius ρ. This vertical gap bounds the distance both from the surface to the wall and from
  // the wall to the surface, since both points share ψ and ρ.
  double fit_error = 0.0;
  double max_error = 0.0;
  int samples = 0;  // surface points measured
};

// Throws InputError unless √2·Rr <= inner < outer and tolerance > 0; NumericalError if the wall is
// not single-valued or the tolerance cannot be met.
GrooveSurface groove_surface(const BarrelCam& cam, int side, const GrooveOptions& options);

}  // namespace polarform
