// SurfaceProjector (declared in point_inversion.h): the sample grid, seams, poles and edges of a
// surface computed once, then Newton point inversion from the grid or from a caller's start.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "src/error.h"
#include "src/nurbs/point_inversion.h"
#include "src/nurbs/surface_jet.h"

namespace polarform {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Grid refinement: neighbouring samples at most this fraction of the control net's size apart,
// with at most kMaxSamples samples per direction.
constexpr double kSpacing = 1.0 / 32.0;
constexpr int kMaxSamples = 160;

// `per_span` equal steps in every non-empty knot span of the domain, plus the domain end.
std::vector<double> span_samples(const Knots& knots, int degree, int n, int per_span) {
  std::vector<double> out;
  for (int i = degree; i < n; ++i)
    for (int m = 0; m < per_span && knots[i + 1] > knots[i]; ++m)
      out.push_back(knots[i] + (knots[i + 1] - knots[i]) * m / per_span);
  out.push_back(knots[n]);
  return out;
}

Eigen::Matrix3Xd grid_points(const NurbsSurface& s, const std::vector<double>& us,
                             const std::vector<double>& vs) {
  const int nv = static_cast<int>(vs.size());
  Eigen::Matrix3Xd g(3, static_cast<Eigen::Index>(us.size()) * nv);
  for (std::size_t a = 0; a < us.size(); ++a)
    for (int b = 0; b < nv; ++b) g.col(static_cast<Eigen::Index>(a) * nv + b) = s.point(us[a], vs[b]);
  return g;
}

// Halves every parameter interval that some grid line crosses with a step longer than `spacing`,
// until none does (or the sample budget is spent): the grid then resolves the surface in space,
// not only in parameter, wherever the parametrization is uneven.
void refine_grid(const NurbsSurface& s, std::vector<double>& us, std::vector<double>& vs,
                 double spacing) {
  for (int round = 0; round < 16; ++round) {
    const Eigen::Matrix3Xd g = grid_points(s, us, vs);
    const int nu = static_cast<int>(us.size()), nv = static_cast<int>(vs.size());
    auto at = [&](int a, int b) { return g.col(static_cast<Eigen::Index>(a) * nv + b); };
    std::vector<double> new_u, new_v;
    for (int a = 0; a + 1 < nu; ++a) {
      double step = 0;
      for (int b = 0; b < nv; ++b) step = std::max(step, (at(a + 1, b) - at(a, b)).norm());
      if (step > spacing) new_u.push_back(0.5 * (us[a] + us[a + 1]));
    }
    for (int b = 0; b + 1 < nv; ++b) {
      double step = 0;
      for (int a = 0; a < nu; ++a) step = std::max(step, (at(a, b + 1) - at(a, b)).norm());
      if (step > spacing) new_v.push_back(0.5 * (vs[b] + vs[b + 1]));
    }
    const bool grow_u = !new_u.empty() && nu + static_cast<int>(new_u.size()) <= kMaxSamples;
    const bool grow_v = !new_v.empty() && nv + static_cast<int>(new_v.size()) <= kMaxSamples;
    if (!grow_u && !grow_v) return;
    if (grow_u) {
      us.insert(us.end(), new_u.begin(), new_u.end());
      std::sort(us.begin(), us.end());
    }
    if (grow_v) {
      vs.insert(vs.end(), new_v.begin(), new_v.end());
      std::sort(vs.begin(), vs.end());
    }
  }
}

// The homogeneous coefficients (dim x count) of an iso-curve, from the folded B-spline view.
Eigen::MatrixXd iso_coefficients(const BSpline& folded, double at, int dim) {
  return folded.point(at).reshaped(dim, folded.dim() / dim);
}

// The interior knots of multiplicity >= degree (C0 iso-lines), with their neighbouring spans.
template <class Crease>
std::vector<Crease> creases(const Knots& knots, int degree) {
  std::vector<Crease> out;
  const double front = knots[degree], back = knots[knots.size() - 1 - degree];
  for (std::size_t i = 0; i < knots.size();) {
    std::size_t j = i;
    while (j < knots.size() && knots[j] == knots[i]) ++j;
    const double at = knots[i];
    if (degree >= 1 && at > front && at < back && int(j - i) >= degree)
      out.push_back({at, at - knots[i - 1], knots[j] - at});
    i = j;
  }
  return out;
}

// Whether a homogeneous control polygon collapses to one point.
bool collapsed(const Eigen::MatrixXd& h, double tol) {
  const Eigen::Index w = h.rows() - 1;
  const Eigen::VectorXd first = h.col(0).head(w) / h(w, 0);
  for (Eigen::Index i = 1; i < h.cols(); ++i)
    if ((h.col(i).head(w) / h(w, i) - first).norm() > tol) return false;
  return true;
}

// Whether two homogeneous control polygons describe the same rational curve: equal Cartesian
// points and proportional weights.
bool same_curve(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double tol) {
  const Eigen::Index w = a.rows() - 1;
  for (Eigen::Index i = 0; i < a.cols(); ++i) {
    const Eigen::VectorXd pa = a.col(i).head(w) / a(w, i), pb = b.col(i).head(w) / b(w, i);
    if ((pa - pb).norm() > tol) return false;
    if (std::abs(a(w, i) / a(w, 0) - b(w, i) / b(w, 0)) > 1e-12 * a(w, i) / a(w, 0)) return false;
  }
  return true;
}

// Moves a parameter by `step` inside [lo, hi]: clamped at an open boundary, wrapped across a seam.
double move(double x, double step, double lo, double hi, bool closed) {
  x += step;
  if (!closed) return std::clamp(x, lo, hi);
  const double period = hi - lo;
  x = lo + std::fmod(x - lo, period);
  return x < lo ? x + period : x;
}

}  // namespace

SurfaceProjector::SurfaceProjector(NurbsSurface surface, int samples_per_span)
    : surface_(std::move(surface)) {
  if (samples_per_span < 0)
    throw InputError("surface projector samples_per_span " + std::to_string(samples_per_span) +
                     ": expected >= 0 (0 = automatic)");
  const NurbsSurface& s = surface_;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int i = 0; i < s.size_u(); ++i)
    for (int j = 0; j < s.size_v(); ++j) {
      lo = lo.cwiseMin(s.control_point(i, j));
      hi = hi.cwiseMax(s.control_point(i, j));
    }
  scale_ = std::max((hi - lo).norm(), std::numeric_limits<double>::min());

  grid_u_ = span_samples(s.knots_u(), s.degree_u(), s.size_u(),
                         samples_per_span > 0 ? samples_per_span : s.degree_u() + 2);
  grid_v_ = span_samples(s.knots_v(), s.degree_v(), s.size_v(),
                         samples_per_span > 0 ? samples_per_span : s.degree_v() + 2);
  refine_grid(s, grid_u_, grid_v_, kSpacing * scale_);
  samples_u_ = static_cast<int>(grid_u_.size());
  samples_v_ = static_cast<int>(grid_v_.size());
  grid_ = grid_points(s, grid_u_, grid_v_);

  // Boundary iso-curves; equal opposite boundaries make a seam, the others are open edges.
  const BSpline along_u = s.homogeneous().along_u(), along_v = s.homogeneous().along_v();
  const Eigen::MatrixXd u0 = iso_coefficients(along_u, s.front_u(), 4);
  const Eigen::MatrixXd u1 = iso_coefficients(along_u, s.back_u(), 4);
  const Eigen::MatrixXd v0 = iso_coefficients(along_v, s.front_v(), 4);
  const Eigen::MatrixXd v1 = iso_coefficients(along_v, s.back_v(), 4);
  const double tol = 1e-12 * scale_;
  closed_u_ = same_curve(u0, u1, tol);
  closed_v_ = same_curve(v0, v1, tol);
  degenerate_ = {collapsed(u0, tol), collapsed(u1, tol), collapsed(v0, tol), collapsed(v1, tol)};
  auto curve = [](int degree, const Knots& knots, const Eigen::MatrixXd& h) {
    return NurbsCurve3d(BSpline(degree, knots, h));
  };
  if (!closed_u_) {
    edges_.push_back({true, s.front_u(), curve(s.degree_v(), s.knots_v(), u0)});
    edges_.push_back({true, s.back_u(), curve(s.degree_v(), s.knots_v(), u1)});
  }
  if (!closed_v_) {
    edges_.push_back({false, s.front_v(), curve(s.degree_u(), s.knots_u(), v0)});
    edges_.push_back({false, s.back_v(), curve(s.degree_u(), s.knots_u(), v1)});
  }
  creases_u_ = creases<Crease>(s.knots_u(), s.degree_u());
  creases_v_ = creases<Crease>(s.knots_v(), s.degree_v());
}

// NURBS Book §6.1, eqs. (6.5)–(6.7): Newton on (r·S_u, r·S_v) = 0 with a descent safeguard
// (Gauss–Newton with a small ridge where the Hessian is not positive definite, step halving),
// an active set at open boundaries and wrap-around across seams. It stops on the zero-cosine
// criterion of the NURBS Book, or when steps no longer shrink at the level of rounding.
SurfaceProjection SurfaceProjector::newton(const Eigen::Vector3d& p, double u, double v) const {
  const NurbsSurface& s = surface_;
  const double fu = s.front_u(), bu = s.back_u(), fv = s.front_v(), bv = s.back_v();
  const double tol = 1e-15 * scale_, small = 1e-7 * scale_;
  double last_small = std::numeric_limits<double>::infinity();
  SurfaceJet j = surface_jet(s, u, v);
  Eigen::Vector3d r = j.s - p;
  double f = r.squaredNorm();
  for (int it = 0; it < 100 && f > tol * tol; ++it) {
    const double gu = r.dot(j.su), gv = r.dot(j.sv);
    // A parameter on an open boundary whose descent direction leaves the domain stays put.
    const bool free_u = closed_u_ || !((u <= fu && gu > 0) || (u >= bu && gu < 0));
    const bool free_v = closed_v_ || !((v <= fv && gv > 0) || (v >= bv && gv < 0));
    const double Guu = j.su.squaredNorm(), Guv = j.su.dot(j.sv), Gvv = j.sv.squaredNorm();
    const bool orthogonal_u = !free_u || gu * gu <= 1e-28 * Guu * f;
    const bool orthogonal_v = !free_v || gv * gv <= 1e-28 * Gvv * f;
    if (orthogonal_u && orthogonal_v) break;
    const double Huu = Guu + r.dot(j.suu), Huv = Guv + r.dot(j.suv), Hvv = Gvv + r.dot(j.svv);
    double du = 0, dv = 0;
    if (free_u && free_v) {
      const double det = Huu * Hvv - Huv * Huv;
      if (Huu > 0 && det > 1e-12 * Huu * Hvv) {
        du = -(Hvv * gu - Huv * gv) / det;
        dv = -(Huu * gv - Huv * gu) / det;
      } else {
        const double ridge = 1e-10 * (Guu + Gvv);
        const double a = Guu + ridge, c = Gvv + ridge, det_g = a * c - Guv * Guv;
        if (!(det_g > 0)) break;  // S_u = S_v = 0: no direction to move
        du = -(c * gu - Guv * gv) / det_g;
        dv = -(a * gv - Guv * gu) / det_g;
      }
    } else {
      const double g = free_u ? gu : gv, H = free_u ? Huu : Hvv, G = free_u ? Guu : Gvv;
      const double h = H > 0 ? H : G;
      if (!(h > 0)) break;
      (free_u ? du : dv) = -g / h;
    }
    // Halve the step until the distance does not grow beyond rounding.
    const double rn = std::sqrt(f), slack = 8.0 * kEps * rn * (rn + p.norm());
    double un = u, vn = v, fn = f;
    Eigen::Vector3d rn_vec = r;
    bool accepted = false;
    for (int halving = 0; halving < 40 && !accepted; ++halving, du *= 0.5, dv *= 0.5) {
      un = move(u, du, fu, bu, closed_u_);
      vn = move(v, dv, fv, bv, closed_v_);
      rn_vec = s.point(un, vn) - p;
      fn = rn_vec.squaredNorm();
      accepted = fn <= f + slack;
    }
    if (!accepted || (un == u && vn == v)) break;
    const double length = (rn_vec - r).norm();
    u = un, v = vn;
    j = surface_jet(s, u, v);
    r = j.s - p;
    f = r.squaredNorm();
    if (length <= tol) break;
    if (length <= small) {
      if (length > 0.5 * last_small) break;  // stagnating at the level of rounding
      last_small = length;
    }
  }
  const Eigen::Vector3d point = s.point(u, v);
  return {u, v, point, (point - p).norm()};
}

// Newton stalls at a C0 crease (the gradient jumps there): a minimum within 1 % of a neighbouring
// span of a crease is searched again from the middle of the span on either side.
SurfaceProjection SurfaceProjector::with_crease_restarts(const Eigen::Vector3d& p,
                                                         SurfaceProjection best) const {
  const SurfaceProjection found = best;
  for (const Crease& c : creases_u_)
    if (std::abs(found.u - c.at) <= 0.01 * std::min(c.left, c.right))
      for (const double u : {c.at - 0.5 * c.left, c.at + 0.5 * c.right})
        if (const SurfaceProjection r = newton(p, u, found.v); r.distance < best.distance) best = r;
  for (const Crease& c : creases_v_)
    if (std::abs(found.v - c.at) <= 0.01 * std::min(c.left, c.right))
      for (const double v : {c.at - 0.5 * c.left, c.at + 0.5 * c.right})
        if (const SurfaceProjection r = newton(p, found.u, v); r.distance < best.distance) best = r;
  return best;
}

// A minimum on an open edge is re-searched on every open boundary curve (robust 1D search): the
// best boundary point may lie on the neighbouring edge, past a corner.
SurfaceProjection SurfaceProjector::with_edge_fallback(const Eigen::Vector3d& p,
                                                       SurfaceProjection best) const {
  const bool on_edge = std::any_of(edges_.begin(), edges_.end(), [&](const Edge& e) {
    return (e.along_v ? best.u : best.v) == e.at;
  });
  if (!on_edge) return best;
  for (const Edge& e : edges_) {
    const CurveProjection c = closest_point(e.curve, p);
    if (c.distance < best.distance) {
      const double u = e.along_v ? e.at : c.u, v = e.along_v ? c.u : e.at;
      const Eigen::Vector3d point = surface_.point(u, v);
      best = {u, v, point, (point - p).norm()};
    }
  }
  return best;
}

SurfaceProjection SurfaceProjector::project(const Eigen::Vector3d& p) const {
  if (!p.allFinite()) throw InputError("point inversion: the query point is not finite");
  const Eigen::VectorXd d2 = (grid_.colwise() - p).colwise().squaredNorm();
  // Local minima of the sampled distance (4-neighbourhood), best first.
  std::vector<int> minima;
  for (int a = 0; a < samples_u_; ++a)
    for (int b = 0; b < samples_v_; ++b) {
      const int k = a * samples_v_ + b;
      const bool is_min = (a == 0 || d2[k] <= d2[k - samples_v_]) &&
                          (a + 1 == samples_u_ || d2[k] <= d2[k + samples_v_]) &&
                          (b == 0 || d2[k] <= d2[k - 1]) && (b + 1 == samples_v_ || d2[k] <= d2[k + 1]);
      if (is_min) minima.push_back(k);
    }
  constexpr std::size_t kStarts = 4;
  const std::size_t starts = std::min(kStarts, minima.size());
  std::partial_sort(minima.begin(), minima.begin() + starts, minima.end(),
                    [&](int x, int y) { return d2[x] < d2[y]; });
  // Best sample of grid row a (fixed u) or column b (fixed v).
  auto best_in_row = [&](int a) {
    int best_b = 0;
    for (int b = 1; b < samples_v_; ++b)
      if (d2[a * samples_v_ + b] < d2[a * samples_v_ + best_b]) best_b = b;
    return best_b;
  };
  auto best_in_column = [&](int b) {
    int best_a = 0;
    for (int a = 1; a < samples_u_; ++a)
      if (d2[a * samples_v_ + b] < d2[best_a * samples_v_ + b]) best_a = a;
    return best_a;
  };
  SurfaceProjection best{0, 0, Eigen::Vector3d::Zero(), std::numeric_limits<double>::infinity()};
  double previous = -1;
  for (std::size_t i = 0; i < starts; ++i) {
    const int k = minima[i];
    if (d2[k] == previous) continue;  // the same sample seen again (a pole or a seam)
    previous = d2[k];
    int a = k / samples_v_, b = k % samples_v_;
    // On a pole every direction is the same point: start on the meridian of the best sample of
    // the neighbouring row (or column), where the other parameter matters.
    if (a == 0 && degenerate_[0]) b = best_in_row(1);
    if (a == samples_u_ - 1 && degenerate_[1]) b = best_in_row(samples_u_ - 2);
    if (b == 0 && degenerate_[2]) a = best_in_column(1);
    if (b == samples_v_ - 1 && degenerate_[3]) a = best_in_column(samples_v_ - 2);
    const SurfaceProjection r = newton(p, grid_u_[a], grid_v_[b]);
    if (r.distance < best.distance) best = r;
  }
  return with_edge_fallback(p, with_crease_restarts(p, best));
}

SurfaceProjection SurfaceProjector::project(const Eigen::Vector3d& p, double u0, double v0) const {
  if (!p.allFinite()) throw InputError("point inversion: the query point is not finite");
  const NurbsSurface& s = surface_;
  if (!(u0 >= s.front_u() && u0 <= s.back_u() && v0 >= s.front_v() && v0 <= s.back_v()))
    throw InputError("point inversion start (" + std::to_string(u0) + ", " + std::to_string(v0) +
                     "): expected a parameter inside the surface domain");
  return with_edge_fallback(p, with_crease_restarts(p, newton(p, u0, v0)));
}

SurfaceProjection closest_point(const NurbsSurface& s, const Eigen::Vector3d& p,
                                int samples_per_span) {
  return SurfaceProjector(s, samples_per_span).project(p);
}

}  // namespace polarform
