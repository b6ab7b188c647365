// A cam program seen from the cam frame: F(φ) = base + s(θ(φ)) as a PolarFunction of the polar
// angle φ = π/2 - σθ of the follower line (cam_frame.h). It is the radial knife-edge contour
// (base = Rb) and the barrel cam's track height (base = z0); being an affine change of variable it
// is exact, and its B-spline form is exact whenever the program's is.
#pragma once

#include "designers/cam/cam_frame.h"
#include "designers/cam/cam_program.h"
#include "designers/convert/polar_function.h"

namespace polarform {

// Domain: [π/2 - 2π, π/2] for a counter-clockwise cam (θ = 0 at the end), [π/2, π/2 + 2π] for a
// clockwise one (θ = 0 at the start); breakpoints at the segment boundaries.
PolarFunction displacement_polar_function(const CamProgram& program, Rotation rotation, double base);

// f(θ) on [0, 2π] as g(φ) = base + f(θ(φ)) on the domain above (knots mirrored for σ = +1).
BSplineFunction displacement_bspline_in_cam_frame(const BSplineFunction& f, Rotation rotation, double base);

}  // namespace polarform
