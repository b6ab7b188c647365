// A plate cam's contour (or pitch curve) as the converter's PolarFunction R(ψ), ψ the polar angle
// of the curve point in the cam frame. θ(ψ) is found by safeguarded Newton iteration to machine
// precision and R', R'', R''' follow from the inverse-function rule, so they are exact. The radial
// knife-edge contour R = Rb + s(θ(ψ)) has ψ affine in θ and gets the exact B-spline form when the
// program is polynomial.
#pragma once

#include <functional>
#include <string>

#include "designers/cam/plate_cam.h"
#include "designers/convert/polar_function.h"

namespace polarform {

enum class CamCurve { Contour, Pitch };

// A closed cam-frame curve traced once as the cam angle θ runs over the program's segments: the
// point's θ-derivatives 0..d (d <= 3) at θ in [start, end] of a segment (one-sided at its ends).
struct CamTrace {
  CamProgram program;  // the segments and the smoothness breaks
  Rotation rotation = Rotation::CounterClockwise;
  std::function<void(int segment, double theta, int d, Eigen::Vector2d* out)> point;
  std::string what;    // the curve in messages: "contour", "groove outer flank", …
  std::string remedy;  // what to change where the curve is not single-valued
};

// As cam_polar_function below, for any traced curve.
PolarFunction traced_polar_function(CamTrace trace);

// Domain: the 2π interval with θ = 0 at its end (counter-clockwise cam: ψ decreases as θ grows)
// or at its start (clockwise); breakpoints are the ψ of the segment boundaries. Throws InputError
// naming the θ range where the curve is not single-valued in ψ (undercut, cusp, loop, or a curve
// that does not wind once around the cam centre). The check samples ~512 angles and refines every
// sampled local minimum of dψ/dθ, so a defect narrower than the sampling that leaves no trace in
// it can escape.
PolarFunction cam_polar_function(const PlateCam& cam, CamCurve curve = CamCurve::Contour);

// The envelope of a roller image (plate_cam.h: a groove's outer flank, a conjugate cam's contour)
// as above; `what` and `remedy` word the error where it is not single-valued.
PolarFunction roller_image_polar_function(const PlateCam& cam, const RollerImage& image,
                                          std::string what, std::string remedy);

}  // namespace polarform
