// Least squares of a spline space to a polar profile r = R(ψ) (NURBS Book §9.4.1, A9.7, on
// samples at fixed ψ): each sample's residual is measured along its radial-error direction, the
// linearised radial error, plus a small share λ of the full distance so that the curve may slide
// along the profile instead of matching the sample's parameter (tangent-distance minimisation;
// Wang, Pottmann & Liu 2006); then Lawson's iteratively reweighted least squares (Lawson 1961)
// pushes the result toward the minimax of those residuals.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "designers/convert/profile_table.h"
#include "designers/convert/spline_space.h"

namespace polarform {

struct ProfileFitOptions {
  int per_span = 8;      // samples per span
  double slide = 1e-2;   // λ: weight of the full distance against the radial one
  int lawson_steps = 0;  // Gauss–Newton steps after the plain fit
  bool reweight = true;  // each with Lawson's reweighting
  // A fit wanted only if its largest sample error meets this target: the steps stop after step k
  // once it exceeds target·(1 + 3/k), from where the steps left rarely reach the target (of 839
  // knot removals so given up on the 66 peer_counts rows, 2 would have met it).
  double target = std::numeric_limits<double>::infinity();
};

struct FittedProfile {
  Eigen::MatrixXd coefs;              // distinct control values, 2 x space.size()
  std::vector<double> sample_errors;  // per span: the largest radial error at the fit's samples
};

// The fit with the smallest largest sample error over the plain fit and its Lawson steps (the
// samples at the middles of per_span equal parts of every span; the normal equations solved by a
// band Cholesky bordered by a periodic space's wrap, bordered_band_cholesky.h).
FittedProfile fit_profile(const SplineSpace& space, const ProfileTable& R,
                          const ProfileFitOptions& options);

// The radial error |ρ − R(ψ)| of the fit at `per_span` + 1 points of every span, the largest per
// span (R from the table).
std::vector<double> span_errors(const SplineSpace& space, const Eigen::MatrixXd& coefs,
                                const ProfileTable& R, int per_span);

}  // namespace polarform
