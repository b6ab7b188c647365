// The wall height of a barrel-cam groove as a tensor-product B-spline function Z(u, ρ) over a
// closed base circle's parameter u and the radius ρ, fitted to h(angle(u), ρ) — the height at the
// polar angle the base circle actually has at u, so the base arcs add no synchronization error.
// Separable least squares on a tensor grid (Bae 2002, Appendix C without constraints; de Boor,
// A Practical Guide to Splines, ch. XVII), closed in u by sharing the seam coefficients, and knots
// refined until the measured max error meets the target.
#pragma once

#include <functional>

#include "src/base/base_circle.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

struct HeightFit {
  BSplineSurface Z;        // dim 1; u over the base circle's domain, v = ρ in [ρ0, ρ1]
  double max_error = 0.0;  // measured max |Z(u, ρ) − h(angle(u), ρ)| on the check grid, mm
  bool constant = false;   // h constant: Z has degree (0, 0)
};

// h(ψ, ρ) → height. Degrees (5, 3), C0 knots (multiplicity 5) at the base arcs' junctions where
// angle(u) has a slope jump, simple knots inside; Z(start, ρ) = Z(end, ρ) exactly. Throws
// NumericalError if the target is not met within the refinement limits.
HeightFit fit_groove_height(const std::function<double(double, double)>& h, const BaseCircle& base,
                            double rho0, double rho1, double target);

}  // namespace polarform
