// A plate cam's contour (or pitch curve) as the converter's PolarFunction R(ψ), ψ the polar angle
// of the curve point in the cam frame. θ(ψ) is found by safeguarded Newton iteration to machine
// precision and R', R'', R''' follow from the inverse-function rule, so they are exact. The radial
// knife-edge contour R = Rb + s(θ(ψ)) has ψ affine in θ and gets the exact B-spline form when the
// program is polynomial.
#pragma once

#include "designers/cam/plate_cam.h"
#include "designers/convert/polar_function.h"

namespace polarform {

enum class CamCurve { Contour, Pitch };

// Domain: the 2π interval with θ = 0 at its end (counter-clockwise cam: ψ decreases as θ grows)
// or at its start (clockwise); breakpoints are the ψ of the segment boundaries. Throws InputError
// naming the θ range where the curve is not single-valued in ψ (undercut, cusp, loop, or a curve
// that does not wind once around the cam centre). The check samples ~512 angles and refines every
// sampled local minimum of dψ/dθ, so a defect narrower than the sampling that leaves no trace in
// it can escape.
PolarFunction cam_polar_function(const PlateCam& cam, CamCurve curve = CamCurve::Contour);

}  // namespace polarform
