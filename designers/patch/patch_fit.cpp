#include "designers/patch/patch_fit.h"

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/fit/point_subset.h"
#include "src/number_text.h"
#include "src/nurbs/coons_surface.h"
#include "src/nurbs/surface_jet.h"

namespace polarform {

namespace {

double seconds(std::chrono::steady_clock::time_point& t0) {
  const auto t1 = std::chrono::steady_clock::now();
  const double s = std::chrono::duration<double>(t1 - t0).count();
  t0 = t1;
  return s;
}

}  // namespace

PatchFit fit_patch(const Eigen::Matrix3Xd& points, const PatchBoundary& boundary,
                   const PatchFitOptions& o) {
  if (points.cols() < 16)
    throw InputError("patch: " + std::to_string(points.cols()) +
                     " points inside the boundary, expected at least 16");
  if (!points.allFinite()) throw InputError("patch: a point has a non-finite coordinate");
  if (o.thin < 0 || o.thin >= 1)
    throw InputError("thinning tolerance " + std::to_string(o.thin) +
                     ": expected a fraction in [0, 1)");
  ProgressRange progress(o.progress, 0.0, 1.0);
  PatchFit r;
  auto t = std::chrono::steady_clock::now();
  // P1, P4–P6: the bilinear Coons patch parametrises every point.
  r.bilinear = bilinear_coons(boundary);
  PatchSearchOptions search = o.search;
  search.threads = o.threads;
  r.decomposition = decompose_surface(r.bilinear, o.decomposition);
  r.timings_s.decomposition += seconds(t);
  r.plane = max_area_plane(r.decomposition.blanket);
  r.parameters = parametrize_on_blanket(points, r.bilinear, r.decomposition.blanket, search);
  r.timings_s.search += seconds(t);
  progress.sub(0.0, 0.3)(1.0);
  // P2–P3: a better base, fitted on a share at the bilinear parameters, parametrises them again.
  BaseSurfaceOptions base = o.base;
  base.threads = o.threads;
  r.base = build_base_surface(boundary, points, r.parameters.u, r.parameters.v,
                              r.parameters.distance, base);
  r.timings_s.base += seconds(t);
  if (base.kind != BaseKind::bilinear) {
    r.decomposition = decompose_surface(r.base.surface, o.decomposition);
    r.timings_s.decomposition += seconds(t);
    r.plane = max_area_plane(r.decomposition.blanket);
    r.parameters = parametrize_on_blanket(points, r.base.surface, r.decomposition.blanket, search);
    r.timings_s.search += seconds(t);
  }
  progress.sub(0.0, 0.5)(1.0);
  // P7: thinning keeps the points nearest to the vertices of a finer blanket.
  std::vector<int> kept;
  if (o.thin > 0) {
    r.thinning = thin_by_base(points, r.base.surface, o.thin, o.decomposition.split);
    kept = r.thinning->kept;
    r.timings_s.thinning += seconds(t);
  }
  // B2: the final fit with the boundary fixed.
  SurfaceFitOptions f;
  f.degree_u = o.degree_u;
  f.degree_v = o.degree_v;
  f.control_u = o.control_u;
  f.control_v = o.control_v;
  f.tolerance = o.tolerance;
  f.boundary = boundary;
  f.correction_rounds = o.correction_rounds;
  f.threads = o.threads;
  // A thinned set leaves some control points without data: a trace of thin-plate energy keeps
  // the system well posed without pulling on the points (as the tensor base does).
  if (o.thin > 0) f.smoothing = 1e-9;
  const Eigen::Matrix3Xd fitted = kept.empty() ? Eigen::Matrix3Xd() : select_columns(points, kept);
  const Eigen::Matrix3Xd& q = kept.empty() ? points : fitted;
  const Eigen::VectorXd qu = kept.empty() ? r.parameters.u : select_entries(r.parameters.u, kept);
  const Eigen::VectorXd qv = kept.empty() ? r.parameters.v : select_entries(r.parameters.v, kept);
  try {
    if (o.control_u == 0 && o.control_v == 0 && !(o.tolerance > 0)) {
      r.net = select_surface_net(q, qu, qv, f);
      f.control_u = r.net->control_u;
      f.control_v = r.net->control_v;
      r.timings_s.net += seconds(t);
    }
    r.fit = fit_surface(q, qu, qv, f);
  } catch (const InputError& e) {
    if (!r.thinning) throw;
    throw InputError("thinning at " + number_text(o.thin * 100) + " % kept " +
                     std::to_string(kept.size()) + " of " + std::to_string(points.cols()) +
                     " points, too few for the surface: " + e.what() +
                     " (thin at a smaller percentage, or give a coarser boundary with --tol)");
  }
  r.timings_s.fit += seconds(t);
  progress.sub(0.5, 0.9)(1.0);
  // Every point's true distance to the final surface: the fit measured its points at their feet;
  // the points thinned out are projected by Newton from their base parameters. Signed by S_u × S_v.
  Eigen::VectorXd d;
  if (kept.empty()) {
    r.u = r.fit.u;
    r.v = r.fit.v;
    d = r.fit.distances;
  } else {
    r.u = r.parameters.u;
    r.v = r.parameters.v;
    for (std::size_t k = 0; k < kept.size(); ++k) {
      r.u[kept[k]] = r.fit.u[static_cast<Eigen::Index>(k)];
      r.v[kept[k]] = r.fit.v[static_cast<Eigen::Index>(k)];
    }
    d = distances_from_parameters(r.fit.surface, points, r.u, r.v, o.threads);
  }
  r.distances.resize(d.size());
  const auto n = static_cast<std::size_t>(d.size());
  parallel_chunks(n, worker_count(o.threads, n, 5000), [&](std::size_t b, std::size_t e, int) {
    for (auto k = static_cast<Eigen::Index>(b); k < static_cast<Eigen::Index>(e); ++k) {
      const SurfaceJet j = surface_jet(r.fit.surface, r.u[k], r.v[k]);  // one evaluation
      r.distances[k] = (points.col(k) - j.s).dot(j.su.cross(j.sv)) < 0 ? -d[k] : d[k];
    }
  });
  r.error = error_stats(r.distances);
  r.timings_s.error += seconds(t);
  progress(1.0);
  return r;
}

}  // namespace polarform
