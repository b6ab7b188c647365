// The follower displacement recovered from scan samples (θ_k, y0 + s_k): a periodic B-spline over
// one revolution (Bae 2002, eqs. (3.9)-(3.10), clipped to [0, 2π]) of degree 5, so that velocity,
// acceleration and jerk are its first three derivatives, fitted with the fairness weight chosen by
// generalized cross-validation (Craven & Wahba 1979) from the data's own noise. The noise floor is
// stated as σ̂ = sqrt(RSS / (n − dof)), dof the fit's effective number of parameters, and the
// recovered curve's mean pointwise standard error as σ̂·sqrt(dof / n) (the trace of the smoother's
// hat matrix is dof; Hastie & Tibshirani 1990, §3.8).
#pragma once

#include <optional>

#include "designers/scan/follower_inversion.h"
#include "src/fit/error_stats.h"
#include "src/nurbs/bspline.h"

namespace polarform {

struct DisplacementFitOptions {
  int degree = 5;
  int spans = 180;  // 2° each over a revolution; GCV decides how much of that freedom is used
  int threads = 2;
  // A fixed fairness weight instead of GCV's: the same smoother applied to other data (the noise
  // propagated through a fit, motion_resolution.h).
  std::optional<double> lambda;
};

struct DisplacementFit {
  BSplineFunction height;       // y0 + s(θ) on [0, 2π], periodic to C^(degree-1)
  double lambda = 0.0;          // fairness weight chosen by GCV
  double dof = 0.0;             // effective parameters
  double noise = 0.0;           // σ̂ of the samples about the fit, mm
  double standard_error = 0.0;  // σ̂·sqrt(dof / n): mean standard error of the fitted s, mm
  ErrorStats residual;          // of the samples about the fit
};

// Throws InputError for fewer samples than twice the spans, or bad options.
DisplacementFit fit_displacement(const FollowerSamples& samples,
                                 const DisplacementFitOptions& options = {});

}  // namespace polarform
