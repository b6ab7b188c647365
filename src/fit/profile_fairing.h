// Fairing a fitted polar profile (MIT 13.472J §8.2.3 on Bae 2002's product form): the fairing acts
// on the polar function F, so C = F·B stays an exact product; Farin's method (knot removal and
// re-insertion) or Kjellander's (F's values at its breakpoints moved onto their neighbours' Hermite
// cubic and re-interpolated, F cubic). A closed profile keeps its seam: Farin moves no control
// point within `degree` of F's ends, Kjellander keeps the end values and tangents. The curve's move
// and its new error against the points are measured, not assumed.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "src/fit/curve_fairing.h"
#include "src/fit/polar_curve_fit.h"

namespace polarform {

enum class FairingMethod { kjellander, farin };
std::string fairing_method_name(FairingMethod method);

struct ProfileFairingOptions {
  FairingMethod method = FairingMethod::farin;
  double tolerance = 0.0;  // mm of radius F; <= 0: 3 × the fit's rms error (its noise estimate)
  int max_passes = 100;
};

// options.tolerance, or 3 × the fit's rms error when it is <= 0; InputError when both are 0.
double fairing_tolerance(const ProfileFairingOptions& options, double rms);

struct ProfileFairing {
  FairingMethod method = FairingMethod::farin;
  double tolerance = 0.0;              // as used (mm)
  std::vector<FairingStep> steps;      // u: F's parameter (the base circle's)
  std::vector<double> step_angle_deg;  // the polar angle of C(u) at each step
  double measured_deviation = 0.0;     // max |C_faired(u) − C(u)| over 20 001 samples (mm)
  double max_jump_before = 0.0, max_jump_after = 0.0;  // of F's p-th derivative
};

// Fairs fit.F, rebuilds fit.curve and re-measures fit.report's error and signed distances on the
// points (the polar fit's input, in its coordinates; outliers left out stay out). Throws InputError
// for Kjellander on a non-cubic F.
ProfileFairing fair_polar_curve(PolarCurveFit& fit, const Eigen::Matrix2Xd& points,
                                const ProfileFairingOptions& options);

}  // namespace polarform
