#include "src/fit/surface_net_selection.h"

#include <algorithm>
#include <cmath>

#include "src/error.h"
#include "src/fit/parallel.h"

namespace polarform {

namespace {

// Every k-th column (and entry) so that at most `count` remain.
struct Subsample {
  Eigen::Matrix3Xd points;
  Eigen::VectorXd u, v;
};
Subsample strided(const Eigen::Matrix3Xd& p, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                  std::size_t count) {
  const Eigen::Index n = p.cols();
  const Eigen::Index step = std::max<Eigen::Index>(
      1, (n + static_cast<Eigen::Index>(count) - 1) / static_cast<Eigen::Index>(count));
  const Eigen::Index m = (n + step - 1) / step;
  Subsample s{Eigen::Matrix3Xd(3, m), Eigen::VectorXd(m), Eigen::VectorXd(m)};
  for (Eigen::Index k = 0; k < m; ++k) {
    s.points.col(k) = p.col(k * step);
    s.u[k] = u[k * step];
    s.v[k] = v[k * step];
  }
  return s;
}

// Least squares at (u, v) with this net, scored by GCV over the coordinates.
SurfaceNetCandidate evaluate(const Subsample& s, SurfaceFitOptions o, int cu, int cv) {
  o.control_u = cu;
  o.control_v = cv;
  o.correction_rounds = 0;
  o.tolerance = 0.0;
  const NurbsSurface f = least_squares_surface(s.points, s.u, s.v, o);
  SurfaceNetCandidate c;
  c.control_u = f.size_u();
  c.control_v = f.size_v();
  const bool fixed = o.boundary.has_value();
  c.free_points =
      static_cast<long>(fixed ? std::max(0, c.control_u - 2) * std::max(0, c.control_v - 2)
                              : c.control_u * c.control_v);
  const auto n = static_cast<std::size_t>(s.points.cols());
  const int chunks = worker_count(o.threads, n, 5000);
  std::vector<double> partial(static_cast<std::size_t>(chunks), 0.0);
  parallel_chunks(n, chunks, [&](std::size_t b, std::size_t e, int chunk) {
    double sum = 0.0;
    for (auto k = static_cast<Eigen::Index>(b); k < static_cast<Eigen::Index>(e); ++k)
      sum += (f.point(s.u[k], s.v[k]) - s.points.col(k)).squaredNorm();
    partial[static_cast<std::size_t>(chunk)] = sum;
  });
  double rss = 0.0;
  for (const double x : partial) rss += x;
  const double nobs = 3.0 * static_cast<double>(n), m = 3.0 * static_cast<double>(c.free_points);
  c.rms = std::sqrt(rss / static_cast<double>(n));
  c.gcv = m < nobs ? (rss / nobs) / ((1 - m / nobs) * (1 - m / nobs)) : INFINITY;
  return c;
}

}  // namespace

SurfaceNetSelection select_surface_net(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u,
                                       const Eigen::VectorXd& v, const SurfaceFitOptions& options) {
  if (points.cols() < 16)
    throw InputError("surface net selection: " + std::to_string(points.cols()) +
                     " points, expected at least 16");
  const Subsample s = strided(points, u, v, kSelectionSamples);
  SurfaceNetSelection r;
  r.samples = static_cast<std::size_t>(s.points.cols());
  const long limit = static_cast<long>(r.samples) / kSamplesPerCoefficient;
  SurfaceNetCandidate best = evaluate(s, options, options.control_u, options.control_v);
  r.candidates.push_back(best);
  const int max_size = std::max(options.max_control_points, 4);
  const auto grown = [](int count, int degree) {  // half again as many spans, at least one more
    const int spans = count - degree;
    return degree + spans + std::max(1, spans / 2);
  };
  SurfaceNetCandidate from = best;  // the growth continues from the latest net
  int without_gain = 0;
  const double size = (s.points.rowwise().maxCoeff() - s.points.rowwise().minCoeff()).norm();
  while (true) {
    if (best.rms <= 1e-12 * size) {
      r.stop = "the points lie on the surface to rounding";
      break;
    }
    const int gu = grown(from.control_u, options.degree_u);
    const int gv = grown(from.control_v, options.degree_v);
    std::vector<std::pair<int, int>> tries;
    if (gu <= max_size) tries.emplace_back(gu, from.control_v);
    if (gv <= max_size) tries.emplace_back(from.control_u, gv);
    if (gu <= max_size && gv <= max_size) tries.emplace_back(gu, gv);
    SurfaceNetCandidate next;
    bool any = false;
    for (const auto& [cu, cv] : tries) {
      const long free_points = static_cast<long>(options.boundary ? (cu - 2) * (cv - 2) : cu * cv);
      if (free_points > limit) continue;
      const auto seen = std::find_if(
          r.candidates.begin(), r.candidates.end(),
          [&](const SurfaceNetCandidate& c) { return c.control_u == cu && c.control_v == cv; });
      const SurfaceNetCandidate c =
          seen != r.candidates.end() ? *seen : evaluate(s, options, cu, cv);
      if (seen == r.candidates.end()) r.candidates.push_back(c);
      if (!any || c.gcv < next.gcv) next = c, any = true;
    }
    if (!any) {
      r.stop = tries.empty() ? "the size limit of " + std::to_string(max_size) + " control points"
                             : "the coefficient rule (one free control point per " +
                                   std::to_string(kSamplesPerCoefficient) + " points)";
      break;
    }
    if (next.gcv < (1 - kGcvImprovement) * best.gcv) {
      best = next;
      without_gain = 0;
    } else if (++without_gain >= 2) {
      r.noise_reached = true;
      r.stop = "GCV stopped improving by 1 % (the residual is at the noise level)";
      break;
    }
    from = next;
  }
  r.control_u = best.control_u;
  r.control_v = best.control_v;
  // The residual is almost all along the normal: σ̂ = sqrt(RSS / (N − free points)).
  const double n = static_cast<double>(r.samples), m = static_cast<double>(best.free_points);
  r.noise = m < n ? best.rms * std::sqrt(n / (n - m)) : best.rms;
  return r;
}

}  // namespace polarform
