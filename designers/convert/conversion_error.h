// Measured conversion error: how far a converted NURBS profile lies from the exact polar function,
// radially (|ρ − R(ψ)| at the polar angle ψ of each curve point) and along the normal, and how much
// the tangent direction turns at the arc junctions (a G1 check). Independent of how the curve was
// built: it evaluates the final NURBS only.
#pragma once

#include <vector>

#include "designers/convert/polar_function.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct ProfileError {
  double max_radial = 0.0;  // mm
  double max_normal = 0.0;  // mm, distance along the normal of the exact curve (first order)
  double at_angle = 0.0;    // polar angle of the max radial error, rad
};

// Error of C over the parameter interval [u0, u1] against R, from `samples` points refined
// around the largest sample by golden-section search.
ProfileError profile_error(const NurbsCurve2d& C, const PolarFunction& R, double u0, double u1,
                           int samples = 32);

// Error of the whole of C against R over the intervals of `grid` (e.g. C's distinct knots), whose
// parameter must approximate the polar angle to within π: `per_interval` + 1 samples in each
// interval, every local maximum of the samples refined by golden-section search.
ProfileError profile_error(const NurbsCurve2d& C, const PolarFunction& R,
                           const std::vector<double>& grid, int per_interval = 8);

// Max angle (rad) between the left and right tangents of C at the given interior parameters.
double max_tangent_jump(const NurbsCurve2d& C, const std::vector<double>& junctions);

// The radial error |ρ − R(ψ)| of C at u and the polar angle ψ; ψ is unwrapped next to `near`.
double radial_error_at(const NurbsCurve2d& C, const PolarFunction& R, double u, double near,
                       double* psi = nullptr);

}  // namespace polarform
