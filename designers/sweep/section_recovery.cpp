// Sweep recovery by sections and skinning along a straight or curved spine (Kantz 2003, §5.4;
// MIT 13.472J §8.6; specs K12, M9).
#include "designers/sweep/section_recovery.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>

#include "src/error.h"
#include "src/fit/local_frame.h"
#include "src/fit/parallel.h"
#include "src/fit/polar_curve_fit.h"
#include "src/number_text.h"
#include "src/nurbs/point_inversion.h"
#include "src/nurbs/skinned_surface.h"

namespace polarform {

namespace {

struct Slices {
  std::vector<SectionSlab> slabs;  // the points in each station's slab
  std::vector<std::string> where;
};

// The points with |s − s_k| <= half for every station s_k (MIT §8.6, step 2: sections at discrete
// stations; Kantz's slab stack).
Slices slice(const Eigen::Matrix3Xd& coords, const std::vector<double>& stations, double half) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(coords.cols()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](Eigen::Index a, Eigen::Index b) { return coords(0, a) < coords(0, b); });
  Slices out;
  for (const double s : stations) {
    const auto lo = std::lower_bound(order.begin(), order.end(), s - half,
                                     [&](Eigen::Index i, double v) { return coords(0, i) < v; });
    const auto hi = std::upper_bound(order.begin(), order.end(), s + half,
                                     [&](double v, Eigen::Index i) { return v < coords(0, i); });
    SectionSlab slab{Eigen::Matrix2Xd(2, hi - lo), Eigen::VectorXd(hi - lo)};
    for (auto it = lo; it != hi; ++it) {
      slab.points.col(it - lo) = coords.block<2, 1>(1, *it);
      slab.along[it - lo] = (coords(0, *it) - s) / half;
    }
    out.slabs.push_back(std::move(slab));
    out.where.push_back("section recovery: the section at s = " + number_text(s) + " mm");
  }
  return out;
}

// The spine through the section centres (MIT §8.6, recovery step 4): a cubic through three or
// more, else (or, unless a curve is asked for, when none leaves it by more than tol) the line
// fitted to them.
SectionSpine spine_through(const std::vector<Eigen::Vector3d>& c, const Eigen::Vector3d& x_hint,
                           SpineShape shape, double tol) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : c) mean += p;
  mean /= static_cast<double>(c.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : c) cov += (p - mean) * (p - mean).transpose();
  Eigen::Vector3d d = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(2);
  if (d.dot(c.back() - c.front()) < 0) d = -d;
  double off = 0.0, lo = 0.0, hi = 0.0;
  for (const Eigen::Vector3d& p : c) {
    const double t = (p - mean).dot(d);
    off = std::max(off, (p - mean - t * d).norm());
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  if (c.size() < 3 || (shape == SpineShape::automatic && off <= tol))
    return SectionSpine::straight(mean + lo * d, d, hi - lo, x_hint);
  return SectionSpine::through(c, x_hint);
}

// Signed true distances of every point to the skin (outward positive: u runs counter-clockwise
// about the tangent, v along it), each projection started at its own angle and arc length.
Eigen::VectorXd skin_distances(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& coords,
                               const NurbsSurface& skin, const std::vector<double>& stations,
                               const SectionCurves& curves, int threads) {
  const SurfaceProjector projector(skin);
  Eigen::VectorXd d(points.cols());
  const auto n = static_cast<std::size_t>(points.cols());
  parallel_chunks(n, worker_count(threads, n, 2000), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t k = b; k < e; ++k) {
      const auto i = static_cast<Eigen::Index>(k);
      const double s = std::clamp(coords(0, i), stations.front(), stations.back());
      const auto up = std::upper_bound(stations.begin(), stations.end(), s);
      std::size_t near = static_cast<std::size_t>(up - stations.begin());
      if (near == stations.size() || (near > 0 && s - stations[near - 1] < stations[near] - s))
        near -= 1;
      const Eigen::Vector2d c = curves.sections[near].centre;
      const double u0 =
          curves.base.parameter(std::atan2(coords(2, i) - c.y(), coords(1, i) - c.x()));
      const SurfaceProjection f = projector.project(points.col(i), u0, s);
      const double side = (points.col(i) - f.point).dot(skin.normal(f.u, f.v));
      d[i] = side < 0 ? -f.distance : f.distance;
    }
  });
  return d;
}

}  // namespace

// Kantz 2003, §5.4 (sections, skinning, adaptive slicing); MIT §8.6 (the curved spine).
SectionRecovery recover_sections(const Eigen::Matrix3Xd& points, const SectionOptions& o) {
  check_sweep_input(points, std::nullopt, "section recovery");
  if (o.initial_sections < 2 || o.max_sections < o.initial_sections)
    throw InputError("section recovery: " + std::to_string(o.initial_sections) +
                     " initial and at most " + std::to_string(o.max_sections) +
                     " sections; expected 2 <= initial <= maximum");
  if (o.points_per_section < 8)
    throw InputError("section recovery: " + std::to_string(o.points_per_section) +
                     " points per section, expected at least 8");
  SectionRecovery out;
  auto t0 = std::chrono::steady_clock::now();
  out.size = (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).norm();
  out.tolerance = o.tolerance > 0 ? o.tolerance : 1e-4 * out.size;
  out.pca = principal_frame(points);
  const int a = out.pca.axis_index(FrameAxis::principal);
  const Eigen::Vector3d axis = out.pca.axes.col(a), x_hint = out.pca.axes.col((a + 1) % 3);
  const Eigen::VectorXd h = (points.colwise() - out.pca.centroid).transpose() * axis;
  if (!(h.maxCoeff() > h.minCoeff()))
    throw InputError("section recovery: the points have no extent along their principal axis");
  SectionSpine spine = SectionSpine::straight(out.pca.centroid + h.minCoeff() * axis, axis,
                                              h.maxCoeff() - h.minCoeff(), x_hint);
  out.timings_s.frame = seconds_since(t0);

  SectionCurveOptions co;
  co.degree = o.degree;
  co.tolerance = out.tolerance / 2;  // half for the sections, half for the skinning between them
  co.threads = o.threads;
  std::vector<double> fractions;
  for (int k = 0; k < o.initial_sections; ++k)
    fractions.push_back(static_cast<double>(k) / (o.initial_sections - 1));
  bool settled = o.spine == SpineShape::straight;
  const double N = static_cast<double>(points.cols());
  for (;;) {
    t0 = std::chrono::steady_clock::now();
    const Eigen::Matrix3Xd coords = spine.coordinates(points, o.threads);
    const double s0 = coords.row(0).minCoeff(), s1 = coords.row(0).maxCoeff();
    const double half = std::max(0.5 * o.points_per_section * (s1 - s0) / N, 1e-9 * out.size);
    std::vector<double> st;
    for (const double f : fractions) st.push_back(s0 + f * (s1 - s0));
    const Slices slices = slice(coords, st, half);
    out.timings_s.slicing += seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    if (!settled) {
      // The centroids of the sections that are closed and star-shaped so far, at the stations or
      // at 9 even ones when there are fewer (enough to bend a straight start towards the ends).
      std::vector<double> probe = st;
      Slices even;
      if (st.size() < 9) {
        probe.clear();
        for (int k = 0; k < 9; ++k) probe.push_back(s0 + (s1 - s0) * k / 8.0);
        even = slice(coords, probe, half);
      }
      const Slices& probes = st.size() < 9 ? even : slices;
      std::vector<Eigen::Vector3d> centres;
      double moved = 0.0;
      for (std::size_t k = 0; k < probe.size(); ++k) {
        try {
          const SectionCurve c =
              fit_section_curve(probes.slabs[k], section_base_circle(), 16, co, probes.where[k]);
          const Eigen::Vector3d p = spine.point(probe[k], c.centroid.x(), c.centroid.y());
          moved = std::max(moved, (p - spine.frame(probe[k]).point).norm());
          centres.push_back(p);
        } catch (const InputError&) {  // not closed or not star-shaped (yet): no centroid
        } catch (const NumericalError&) {
        }
      }
      out.timings_s.sections += seconds_since(t0);
      if (centres.size() >= 2 && moved > out.tolerance / 4 &&
          out.spine_iterations < o.max_spine_iterations) {
        spine = spine_through(centres, x_hint, o.spine, out.tolerance);
        ++out.spine_iterations;
        continue;
      }
      settled = true;
      t0 = std::chrono::steady_clock::now();
    }
    SectionCurveOptions common = co;
    common.centre = Eigen::Vector2d::Zero();  // the spine, through the centroids once settled
    const SectionCurves curves = fit_section_curves(slices.slabs, common, slices.where);
    out.timings_s.sections += seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    std::vector<NurbsCurve3d> placed;
    for (std::size_t k = 0; k < st.size(); ++k) {
      const SpineFrame f = spine.frame(st[k]);
      LocalFrame plane;
      plane.origin = f.point;
      plane.axes << f.x, f.y, f.tangent;
      placed.push_back(curve_in_space(curves.sections[k].curve, plane));
    }
    const NurbsSurface skin = skin_sections(placed, st);
    out.timings_s.skin += seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    const Eigen::VectorXd d = skin_distances(points, coords, skin, st, curves, o.threads);
    out.timings_s.error += seconds_since(t0);
    ++out.rounds;

    // Adaptive slicing (Kantz 2003, §5.4; spec K12 step 6): a station halves every span whose
    // points the skin misses by more than half the tolerance beyond what its two sections' fits
    // leave (on noise-free data the sections' own half, so the skin stays within the tolerance).
    std::vector<double> worst(st.size() - 1, 0.0);
    for (Eigen::Index i = 0; i < d.size(); ++i) {
      const auto up = std::upper_bound(st.begin(), st.end(), coords(0, i));
      const std::size_t span =
          std::clamp<std::size_t>(static_cast<std::size_t>(up - st.begin()), 1, st.size() - 1) - 1;
      worst[span] = std::max(worst[span], std::abs(d[i]));
    }
    std::vector<double> next;
    int room = o.max_sections - static_cast<int>(st.size());
    for (std::size_t k = 0; k + 1 < st.size(); ++k) {
      next.push_back(fractions[k]);
      const double bound = out.tolerance / 2 +
                           std::max(curves.sections[k].error.max, curves.sections[k + 1].error.max);
      if (worst[k] > bound && st[k + 1] - st[k] >= 2 * half && room > 0) {
        next.push_back(0.5 * (fractions[k] + fractions[k + 1]));
        --room;
      }
    }
    next.push_back(fractions.back());
    if (next.size() == fractions.size()) {
      // Done: fill the result.
      out.spine = spine;
      out.spine_curved = !spine.straight();
      out.spine_length = st.back() - st.front();
      out.slab = half;
      out.spans = curves.size;
      out.surfaces = {skin};
      out.distances = d;
      out.error = error_stats(d);
      out.unexplained = 0;
      for (Eigen::Index i = 0; i < d.size(); ++i) out.unexplained += std::abs(d[i]) > out.tolerance;
      out.plane = coords.bottomRows(2);
      out.s = coords.row(0).transpose();
      out.profile.size = out.size;
      out.profile.tolerance = out.tolerance;
      for (std::size_t k = 0; k < st.size(); ++k) {
        const SectionCurve& c = curves.sections[k];
        MeridianLoop l;
        l.curve = c.curve;
        l.closed = true;
        l.points = slices.slabs[k].points;
        l.fit_max = c.error.max;
        l.tolerance_met = c.error.max <= out.tolerance;
        out.profile.loops.push_back(std::move(l));
        out.stations.push_back({st[k], spine.point(st[k], c.centroid.x(), c.centroid.y()),
                                static_cast<std::size_t>(slices.slabs[k].points.cols()), c,
                                placed[k]});
      }
      out.profile.clusters = static_cast<int>(points.cols());
      return out;
    }
    fractions = std::move(next);
    settled = o.spine == SpineShape::straight;
  }
}

}  // namespace polarform
