// Fairing a fitted surface (MIT 13.472J §8.2.4 on Bae 2002's product form S = F·B): Farin's or
// Kjellander's fairing acts on the rows and columns of F's net — along u (every row at once, one
// knot of u per pass), then along v, each with half the tolerance — and S is rebuilt as the exact
// product of the faired F. A closed v keeps its seam (Farin moves no control row within `degree`
// of its ends, Kjellander keeps the end values and tangents), and so does u on a spherical fit
// (its poles; a G0 pole's constant row also stays constant along v, a G1 pole would not and is
// refused, as is a cap). The surface's move and its new error against the points are measured.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/fit/curve_fairing.h"
#include "src/fit/cylindrical_fit.h"
#include "src/fit/profile_fairing.h"
#include "src/fit/spherical_fit.h"

namespace polarform {

// The fairing of one direction of F's net.
struct NetDirectionFairing {
  std::vector<FairingStep> steps;                      // u: knots of that direction
  // Of F's p-th derivative across them, as this pass found and left the net (v runs after u).
  double max_jump_before = 0.0, max_jump_after = 0.0;
  double bound = 0.0;  // Farin: Σ of the steps' bounds; Kjellander: the largest data move (mm)
};

struct SurfaceFitFairing {
  FairingMethod method = FairingMethod::farin;
  double tolerance = 0.0;  // as used (mm): 3 × the fit's rms error unless given
  NetDirectionFairing u, v;
  double measured_deviation = 0.0;  // max |S_faired − S| over 201 × 201 parameters (mm)
  double error_before = 0.0;        // the fit's max point distance before fairing (mm)
};

// Fairs fit.F, rebuilds fit.surface (and the seam report) and re-measures fit.report's error and
// signed distances by true closest points (outliers left out stay out). `points` are the fit's
// input in global coordinates. Throws InputError for Kjellander on a non-cubic F, and for a
// spherical fit with a G1 pole or a pole cap (built from the surface it closes).
SurfaceFitFairing fair_cylindrical_fit(CylindricalFit& fit, const Eigen::Matrix3Xd& points,
                                       const ProfileFairingOptions& options);
SurfaceFitFairing fair_spherical_fit(SphericalFit& fit, const Eigen::Matrix3Xd& points,
                                     const ProfileFairingOptions& options);

}  // namespace polarform
