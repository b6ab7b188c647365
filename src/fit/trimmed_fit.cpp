#include "src/fit/trimmed_fit.h"

#include "src/fit/fit_pipeline.h"
#include "src/fit/point_distances.h"

namespace polarform {

TrimmedFit fit_trimmed(Samples samples, const Eigen::Matrix3Xd& local, const FunctionSpace& space,
                       const FunctionFitOptions& options, const GeometryOf& geometry,
                       const std::vector<Eigen::Index>& leave_out,
                       const ModelChoiceOptions& model) {
  const int threads = options.threads;
  TrimmedFit r;
  if (leave_out.empty()) {
    ModelChoice c = choose_model(samples, space, options, model);
    r.net = std::move(c.net);
    r.revolution = std::move(c.revolution);
    r.fit = fit_function(
        samples, c.space, c.options,
        distance_measure(geometry, local, samples, threads, &r.unconverged, &r.restarted));
    r.kept = std::move(samples);
    return r;
  }
  std::vector<char> out(samples.size(), 0);
  for (Eigen::Index k : leave_out) out[static_cast<std::size_t>(k)] = 1;
  const Eigen::Index n = static_cast<Eigen::Index>(samples.size() - leave_out.size());
  Samples& kept = r.kept;
  kept.u.resize(n), kept.v.resize(n), kept.value.resize(n);
  if (samples.weight.size()) kept.weight.resize(n);
  Eigen::Matrix3Xd kept_local(3, n);
  for (Eigen::Index k = 0, a = 0; k < samples.value.size(); ++k) {
    if (out[static_cast<std::size_t>(k)]) continue;
    kept.u[a] = samples.u[k], kept.v[a] = samples.v[k], kept.value[a] = samples.value[k];
    if (samples.weight.size()) kept.weight[a] = samples.weight[k];
    kept_local.col(a++) = local.col(k);
  }
  std::size_t unconverged = 0;
  ModelChoice c = choose_model(kept, space, options, model);
  r.net = std::move(c.net);
  r.revolution = std::move(c.revolution);
  r.fit = fit_function(kept, c.space, c.options,
                       distance_measure(geometry, kept_local, kept, threads, &unconverged));
  const PointDistances all =
      point_distances(geometry(r.fit.F), local, samples.u, samples.v, threads);
  r.fit.errors = all.signed_distance;
  r.unconverged = all.unconverged;
  r.restarted = all.restarted;
  return r;
}

}  // namespace polarform
