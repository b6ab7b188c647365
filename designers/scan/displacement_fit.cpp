#include "designers/scan/displacement_fit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/error.h"
#include "src/fit/function_fit.h"

namespace polarform {

DisplacementFit fit_displacement(const FollowerSamples& s, const DisplacementFitOptions& o) {
  if (o.degree < 3 || o.degree > 9 || o.spans < o.degree + 1)
    throw InputError("displacement fit: degree " + std::to_string(o.degree) + " and " +
                     std::to_string(o.spans) +
                     " spans; expected a degree from 3 to 9 and more spans than the degree");
  if (s.theta.size() < 2 * o.spans)
    throw InputError("displacement fit: " + std::to_string(s.theta.size()) +
                     " contour samples for " + std::to_string(o.spans) +
                     " spans; expected at least two per span");
  Samples samples;
  samples.u = Eigen::VectorXd::Zero(s.theta.size());
  samples.v = s.theta;
  samples.value = s.height;
  FunctionFitOptions fo;
  fo.degree_u = 0;
  fo.size_u = fo.max_size_u = 1;
  fo.degree_v = o.degree;
  fo.size_v = o.spans;
  fo.fairness.mode = o.lambda ? FairnessOptions::Mode::fixed : FairnessOptions::Mode::gcv;
  if (o.lambda) fo.fairness.weight = *o.lambda;
  fo.reduce_constant = false;
  fo.threads = o.threads;
  const FunctionSpace space{0.0, 1.0, 0.0, 2 * std::numbers::pi, true};
  const FunctionFitResult fit = fit_function(samples, space, fo);
  DisplacementFit out;
  out.height = BSplineFunction(fit.F.degree_v(), fit.F.knots_v(), fit.F.coefs().row(0).transpose());
  out.lambda = fit.lambda;
  out.dof = fit.dof;
  out.residual = fit.stats;
  const double n = static_cast<double>(s.theta.size());
  out.noise = std::sqrt(fit.errors.squaredNorm() / std::max(1.0, n - fit.dof));
  out.standard_error = out.noise * std::sqrt(std::max(0.0, fit.dof) / n);
  return out;
}

}  // namespace polarform
