#include "src/fit/fit_pipeline.h"

namespace polarform {

Eigen::VectorXd synchronize(const BaseCircle& circle, const Eigen::VectorXd& angle, int threads) {
  Eigen::VectorXd u(angle.size());
  const std::size_t n = static_cast<std::size_t>(angle.size());
  parallel_chunks(n, worker_count(threads, n), [&](std::size_t b, std::size_t e, int) {
    circle.parameters(angle.data() + b, u.data() + b, e - b);
  });
  return u;
}

FunctionFitOptions with_progress_range(const FunctionFitOptions& opt, double from, double to) {
  FunctionFitOptions o = opt;
  if (opt.progress) {
    const ProgressFn sink = opt.progress;
    o.progress = [sink, from, to](double f) { sink(from + (to - from) * f); };
  }
  return o;
}

FitReport make_report(FunctionFitResult& fit, int nurbs_degree_u, int nurbs_degree_v, int nurbs_size_u,
                      int nurbs_size_v, const Samples& samples, int threads, std::size_t unconverged,
                      StageTimes times) {
  FitReport r;
  r.degree_u = fit.F.degree_u();
  r.degree_v = fit.F.degree_v();
  r.size_u = fit.size_u;
  r.size_v = fit.size_v;
  r.nurbs_degree_u = nurbs_degree_u;
  r.nurbs_degree_v = nurbs_degree_v;
  r.nurbs_size_u = nurbs_size_u;
  r.nurbs_size_v = nurbs_size_v;
  r.lambda = fit.lambda;
  r.dof = fit.dof;
  r.refinements = fit.refinements;
  r.error = fit.stats;
  r.signed_distance = std::move(fit.errors);
  StageClock clock;
  r.radial = error_stats(parametric_residuals(fit.F, samples, threads));
  r.unconverged = unconverged;
  times.knots += fit.times.knots;
  times.assembly += fit.times.assembly;
  times.solve += fit.times.solve;
  times.product += fit.times.product;
  times.error += fit.times.error + clock.lap();
  r.times = times;
  return r;
}

}  // namespace polarform
