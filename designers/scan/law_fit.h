// One rise or return of a recovered follower motion fitted by one motion law with free boundary
// angles, start level and lift: the model y(θ) = y_a + h·S((θ − θa)/(θb − θa)), S the normalised
// law clamped to 0 before θa and to 1 after θb, fitted to the displacement samples of a window
// about the motion by Levenberg–Marquardt (Marquardt 1963) on the residual in y. An SCCA law has
// its fractions b and d free as well (c = 1 − b − d, kept in the simplex). The parameters'
// covariance is σ²·(JᵀJ)⁻¹ at the optimum with σ the scan's stated noise (Seber & Wild 1989, §2.1).
#pragma once

#include <Eigen/Core>

#include "designers/cam/motion_law.h"
#include "designers/cam/scca_law.h"

namespace polarform {

// Displacement samples of one window, angles unwrapped into the window (increasing not needed).
struct LawWindow {
  Eigen::VectorXd theta;   // rad
  Eigen::VectorXd height;  // y0 + s, mm
};

// A law to fit: a standard law, or MotionLaw::Scca with its starting fractions. A return of a law
// that is not antisymmetric (the double harmonic) runs its rise backwards: the fraction of the
// lift travelled is 1 − S(1 − x) (normalised_law.h).
struct LawShape {
  MotionLaw law = MotionLaw::Cycloidal;
  SccaParameters scca;    // Scca only: the start of the search
  bool reversed = false;  // 1 − S(1 − x): the return of a law whose rise is not antisymmetric
};

struct LawFit {
  LawShape shape;      // the law; for SCCA the fitted fractions
  double start = 0.0;  // θa, rad (in the window's unwrapped angles)
  double end = 0.0;    // θb, rad
  double level = 0.0;  // y_a, mm
  double lift = 0.0;   // h, mm: > 0 rising, < 0 returning
  int parameters = 4;  // 4, or 6 for SCCA
  double rss = 0.0;    // Σ residual², mm²
  std::size_t count = 0;
  // Standard deviations of start, end, level, lift (and b, d for SCCA) from the covariance.
  Eigen::VectorXd sd;
  double rms() const;
};

// S, S', S'' of a law shape at x (clamped to [0, 1]); SCCA through SccaLaw.
void law_shape_derivatives(const LawShape& shape, double x, double* out);

// Fits `shape` to the window from the guess (start, end, level, lift of `guess`; its shape is
// ignored). noise: the samples' standard deviation σ, mm. Throws InputError for fewer samples
// than 4 per parameter or a guess with end <= start.
LawFit fit_law(const LawWindow& window, const LawShape& shape, const LawFit& guess, double noise);

}  // namespace polarform
