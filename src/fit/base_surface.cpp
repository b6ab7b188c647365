#include "src/fit/base_surface.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "src/error.h"
#include "src/fit/bicubic_coons_fit.h"
#include "src/fit/parallel.h"
#include "src/fit/point_subset.h"
#include "src/fit/surface_fit.h"
#include "src/nurbs/coons_surface.h"
#include "src/nurbs/point_inversion.h"

namespace polarform {

namespace {

// A random share of the indices 0..n-1 (at least `minimum`), increasing.
std::vector<int> random_share(int n, double share, int minimum) {
  std::vector<int> all(static_cast<std::size_t>(n));
  std::iota(all.begin(), all.end(), 0);
  const int k = std::min(n, std::max(minimum, static_cast<int>(std::lround(share * n))));
  std::mt19937 rng(20011);
  std::shuffle(all.begin(), all.end(), rng);
  all.resize(static_cast<std::size_t>(k));
  std::sort(all.begin(), all.end());
  return all;
}

void measure(BaseSurface& b, const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u,
             const Eigen::VectorXd& v, int threads) {
  b.u = u;
  b.v = v;
  b.distances = distances_from_parameters(b.surface, points, b.u, b.v, threads);
  b.max_distance = b.distances.size() ? b.distances.maxCoeff() : 0.0;
  b.rms_distance =
      b.distances.size()
          ? std::sqrt(b.distances.squaredNorm() / static_cast<double>(b.distances.size()))
          : 0.0;
}

}  // namespace

std::string base_kind_name(BaseKind kind) {
  switch (kind) {
    case BaseKind::bilinear:
      return "bilinear";
    case BaseKind::bicubic:
      return "bicubic";
    case BaseKind::tensor:
      return "tensor";
  }
  return "?";
}

Eigen::VectorXd distances_from_parameters(const NurbsSurface& surface,
                                          const Eigen::Matrix3Xd& points, Eigen::VectorXd& u,
                                          Eigen::VectorXd& v, int threads) {
  const SurfaceProjector projector(surface);
  const auto n = static_cast<std::size_t>(points.cols());
  Eigen::VectorXd d(points.cols());
  parallel_chunks(n, worker_count(threads, n, 2000), [&](std::size_t b, std::size_t e, int) {
    for (auto k = static_cast<Eigen::Index>(b); k < static_cast<Eigen::Index>(e); ++k) {
      const SurfaceProjection f = projector.project(points.col(k), u[k], v[k]);
      u[k] = f.u;
      v[k] = f.v;
      d[k] = f.distance;
    }
  });
  return d;
}

BaseSurface build_base_surface(const PatchBoundary& boundary, const Eigen::Matrix3Xd& points,
                               const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                               const Eigen::VectorXd& distances, const BaseSurfaceOptions& o) {
  if (!(o.share > 0 && o.share <= 1))
    throw InputError("base share " + std::to_string(o.share) + ": expected a fraction in (0, 1]");
  BaseSurface b;
  b.kind = o.kind;
  const int n = static_cast<int>(points.cols());
  if (o.kind == BaseKind::bilinear) {
    b.surface = bilinear_coons(boundary);
    b.u = u;
    b.v = v;
    b.distances = distances;
    b.max_distance = distances.size() ? distances.maxCoeff() : 0.0;
    b.rms_distance =
        distances.size()
            ? std::sqrt(distances.squaredNorm() / static_cast<double>(distances.size()))
            : 0.0;
    return b;
  }
  const std::vector<int> share = random_share(n, o.share, std::min(n, 64));
  const Eigen::Matrix3Xd q = select_columns(points, share);
  const Eigen::VectorXd su = select_entries(u, share), sv = select_entries(v, share);
  b.fitted_points = static_cast<int>(share.size());
  if (o.kind == BaseKind::tensor) {
    SurfaceFitOptions f;
    f.degree_u =
        o.degree_u > 0 ? o.degree_u : std::max({2, boundary.u0.degree(), boundary.u1.degree()});
    f.degree_v =
        o.degree_v > 0 ? o.degree_v : std::max({2, boundary.v0.degree(), boundary.v1.degree()});
    f.control_u = o.control_u;
    f.control_v = o.control_v;
    f.boundary = boundary;
    f.threads = o.threads;
    f.smoothing = 1e-9;  // keeps nets with empty spans well posed; negligible elsewhere
    b.surface = fit_surface(q, su, sv, f).surface;
    measure(b, points, u, v, o.threads);
    return b;
  }
  // Bicubic Coons: the unscaled and/or the scaled derivatives, the nearer one kept.
  BaseSurface best;
  bool have = false;
  for (const bool scaled : {false, true}) {
    if ((o.cross_scale == CrossScale::yes && !scaled) ||
        (o.cross_scale == CrossScale::no && scaled))
      continue;
    BicubicCoonsFitOptions f;
    f.scale_cross_derivatives = scaled;
    const BicubicCoonsFit fit = fit_bicubic_coons(boundary, q, su, sv, f);
    BaseSurface c = b;
    c.surface = fit.surface;
    c.cross_scaled = scaled;
    c.twist_mismatch = fit.twist_mismatch;
    measure(c, points, u, v, o.threads);
    (scaled ? b.scaled_max_distance : b.unscaled_max_distance) = c.max_distance;
    if (!have || c.max_distance < best.max_distance) {
      best = std::move(c);
      have = true;
    }
  }
  best.scaled_max_distance = b.scaled_max_distance;
  best.unscaled_max_distance = b.unscaled_max_distance;
  return best;
}

}  // namespace polarform
