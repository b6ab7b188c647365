// Parametric tensor-product LSQ surface fit (Piegl & Tiller 2001, §2.3, §4; spec B2): banded
// normal equations assembled once from the (p+1)(q+1) non-zero basis products of every point,
// fixed boundary coefficients moved to the right-hand side, one sparse LDLᵀ factorisation for x, y
// and z, knot insertion in the worst spans to a tolerance and Hoschek correction rounds.
#include "src/fit/surface_fit.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/fit/fairness.h"
#include "src/fit/parallel.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/common_basis.h"
#include "src/nurbs/degree_elevation.h"
#include "src/nurbs/knot_refinement.h"
#include "src/nurbs/point_inversion.h"

namespace polarform {

namespace {

// The two opposite boundary curves of one direction on one basis (rows 0-3: first curve, 4-7:
// second, homogeneous with unit weights), or empty without a boundary.
struct BoundaryPair {
  BSpline curves;
  bool present() const { return curves.size() > 0; }
};

BSpline elevated_to(const NurbsCurve3d& c, int degree, const char* name) {
  if (c.is_rational())
    throw InputError(std::string("surface fit: boundary ") + name + " is rational");
  if (std::abs(c.front()) > 1e-12 || std::abs(c.back() - 1.0) > 1e-12)
    throw InputError(std::string("surface fit: boundary ") + name + " must have the domain [0, 1]");
  if (c.degree() > degree)
    throw InputError(std::string("surface fit: boundary ") + name + " has degree " +
                     std::to_string(c.degree()) + ", above the surface degree " +
                     std::to_string(degree));
  return elevate_degree(c.homogeneous(), degree - c.degree());
}

// NURBS Book A5.9 + A5.4 via common_basis: both curves on the union of their knots.
BoundaryPair boundary_pair(const NurbsCurve3d& a, const NurbsCurve3d& b, int degree,
                           const char* name_a, const char* name_b) {
  return {common_basis({elevated_to(a, degree, name_a), elevated_to(b, degree, name_b)})};
}

// Knot values halving the widest spans (the first on ties) until the count reaches `count`.
std::vector<double> uniform_insertions(const Knots& knots, int degree, int count) {
  Knots k = knots;
  std::vector<double> added;
  while (static_cast<int>(k.size()) - degree - 1 < count) {
    int widest = degree;
    for (int i = degree; i + 1 < static_cast<int>(k.size()) - degree; ++i)
      if (k[i + 1] - k[i] > k[widest + 1] - k[widest]) widest = i;
    const double mid = 0.5 * (k[widest] + k[widest + 1]);
    added.push_back(mid);
    k.insert(k.begin() + widest + 1, mid);
  }
  std::sort(added.begin(), added.end());
  return added;
}

// One direction of the net: its knots and, with a boundary, the two fixed curves on them.
struct Direction {
  int degree = 3;
  Knots knots;
  BoundaryPair boundary;
  int size() const { return static_cast<int>(knots.size()) - degree - 1; }
  void insert(const std::vector<double>& values) {
    if (values.empty()) return;
    if (boundary.present()) {
      boundary.curves = refine_knots(boundary.curves, values);
      knots = boundary.curves.knots();
    } else {
      Knots k = knots;
      k.insert(k.end(), values.begin(), values.end());
      std::sort(k.begin(), k.end());
      knots = std::move(k);
    }
  }
};

Direction make_direction(int degree, int count, const std::optional<BoundaryPair>& pair,
                         const char* axis) {
  Direction d;
  d.degree = degree;
  if (pair) {
    d.boundary = *pair;
    d.knots = pair->curves.knots();
    if (count > 0 && count < d.size())
      throw InputError(std::string("surface fit: ") + std::to_string(count) +
                       " control points in " + axis + ", fewer than the boundary curves' " +
                       std::to_string(d.size()));
    d.insert(uniform_insertions(d.knots, degree, count));
  } else {
    const int n = count > 0 ? count : 4;
    if (n < degree + 1)
      throw InputError(std::string("surface fit: ") + std::to_string(n) + " control points in " +
                       axis + ", expected at least degree + 1 = " + std::to_string(degree + 1));
    d.knots = uniform_clamped_knots(degree, n - degree, 0.0, 1.0);
  }
  return d;
}

// Normal equations in band form: entry ((i, j), (i + di, j + dj)) for |di| <= p, |dj| <= q.
class BandSystem {
 public:
  BandSystem(int nu, int nv, int p, int q)
      : nu_(nu),
        nv_(nv),
        p_(p),
        q_(q),
        wu_(2 * p + 1),
        wv_(2 * q + 1),
        G_(static_cast<std::size_t>(nu) * nv * wu_ * wv_, 0.0),
        R_(3, nu * nv) {
    R_.setZero();
  }
  double& at(int a, int b, int di, int dj) {
    return G_[((static_cast<std::size_t>(a) * nv_ + b) * wu_ + di + p_) * wv_ + dj + q_];
  }
  double at(int a, int b, int di, int dj) const {
    return G_[((static_cast<std::size_t>(a) * nv_ + b) * wu_ + di + p_) * wv_ + dj + q_];
  }
  Eigen::Matrix3Xd& rhs() { return R_; }
  void add(const BandSystem& o) {
    for (std::size_t k = 0; k < G_.size(); ++k) G_[k] += o.G_[k];
    R_ += o.R_;
  }
  int nu() const { return nu_; }
  int nv() const { return nv_; }
  int p() const { return p_; }
  int q() const { return q_; }

 private:
  int nu_, nv_, p_, q_, wu_, wv_;
  std::vector<double> G_;
  Eigen::Matrix3Xd R_;
};

// Σ_k B_a(u_k, v_k) B_b(u_k, v_k) and Σ_k B_a Q_k over the local (p+1)(q+1) basis of each point.
void assemble_points(BandSystem& sys, const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u,
                     const Eigen::VectorXd& v, const Direction& du, const Direction& dv,
                     std::size_t begin, std::size_t end) {
  const int p = du.degree, q = dv.degree;
  double Nu[kMaxDegree + 1], Nv[kMaxDegree + 1], B[(kMaxDegree + 1) * (kMaxDegree + 1)];
  for (std::size_t k = begin; k < end; ++k) {
    const int su = find_span(p, du.knots, du.size(), u[k]);
    const int sv = find_span(q, dv.knots, dv.size(), v[k]);
    basis_funs(su, u[k], p, du.knots, Nu);
    basis_funs(sv, v[k], q, dv.knots, Nv);
    for (int a = 0; a <= p; ++a)
      for (int b = 0; b <= q; ++b) B[a * (q + 1) + b] = Nu[a] * Nv[b];
    const Eigen::Vector3d Q = points.col(static_cast<Eigen::Index>(k));
    for (int a = 0; a <= p; ++a)
      for (int b = 0; b <= q; ++b) {
        const double w = B[a * (q + 1) + b];
        const int i = su - p + a, j = sv - q + b;
        sys.rhs().col(i * sys.nv() + j) += w * Q;
        double* row = &sys.at(i, j, -a, -b);  // (di, dj) = (c - a, d - b), dj fastest
        const int wv = 2 * q + 1;
        for (int c = 0; c <= p; ++c)
          for (int d = 0; d <= q; ++d) row[c * wv + d] += w * B[c * (q + 1) + d];
      }
  }
}

// λ ∫∫ |S_uu|² + 2|S_uv|² + |S_vv|² as tensor products of 1D Gram matrices (thin-plate energy).
void add_thin_plate(BandSystem& sys, const Direction& du, const Direction& dv, double lambda) {
  const SplineAxis au{du.degree, du.knots, false}, av{dv.degree, dv.knots, false};
  const Eigen::MatrixXd u0 = derivative_gram(au, 0), u1 = derivative_gram(au, 1),
                        u2 = derivative_gram(au, 2);
  const Eigen::MatrixXd v0 = derivative_gram(av, 0), v1 = derivative_gram(av, 1),
                        v2 = derivative_gram(av, 2);
  const int p = du.degree, q = dv.degree;
  for (int i = 0; i < sys.nu(); ++i)
    for (int k = std::max(0, i - p); k <= std::min(sys.nu() - 1, i + p); ++k)
      for (int j = 0; j < sys.nv(); ++j)
        for (int l = std::max(0, j - q); l <= std::min(sys.nv() - 1, j + q); ++l)
          sys.at(i, j, k - i, l - j) +=
              lambda * (u2(i, k) * v0(j, l) + 2.0 * u1(i, k) * v1(j, l) + u0(i, k) * v2(j, l));
}

// The net with the fixed boundary rows/columns filled in (NaN elsewhere) and the fixed mask.
struct FixedNet {
  Eigen::Matrix3Xd values;
  std::vector<char> fixed;
};

FixedNet fixed_net(const Direction& du, const Direction& dv) {
  const int nu = du.size(), nv = dv.size();
  FixedNet f{Eigen::Matrix3Xd::Zero(3, nu * nv), std::vector<char>(nu * nv, 0)};
  if (!du.boundary.present()) return f;
  auto set = [&](int i, int j, const Eigen::Vector3d& x) {
    f.values.col(i * nv + j) = f.fixed[i * nv + j] ? 0.5 * (f.values.col(i * nv + j) + x) : x;
    f.fixed[i * nv + j] = 1;
  };
  const Eigen::MatrixXd& cu = du.boundary.curves.coefs();  // u0 rows 0-2, u1 rows 4-6
  const Eigen::MatrixXd& cv = dv.boundary.curves.coefs();  // v0 rows 0-2, v1 rows 4-6
  for (int i = 0; i < nu; ++i) {
    set(i, 0, cu.col(i).segment<3>(0));
    set(i, nv - 1, cu.col(i).segment<3>(4));
  }
  for (int j = 0; j < nv; ++j) {
    set(0, j, cv.col(j).segment<3>(0));
    set(nu - 1, j, cv.col(j).segment<3>(4));
  }
  return f;
}

// Least squares with the fixed coefficients on the right-hand side; one LDLᵀ, three solves.
NurbsSurface solve_net(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u,
                       const Eigen::VectorXd& v, const Direction& du, const Direction& dv,
                       double smoothing, int threads) {
  const int nu = du.size(), nv = dv.size(), p = du.degree, q = dv.degree;
  const FixedNet net = fixed_net(du, dv);
  std::vector<int> unknown(nu * nv, -1);
  int free_count = 0;
  for (int c = 0; c < nu * nv; ++c)
    if (!net.fixed[c]) unknown[c] = free_count++;
  if (smoothing <= 0.0 && points.cols() < free_count)
    throw InputError("surface fit: " + std::to_string(points.cols()) + " points for " +
                     std::to_string(free_count) +
                     " free control points; give more points, fewer control points or smoothing");
  const std::size_t n = static_cast<std::size_t>(points.cols());
  const int chunks = worker_count(threads, n, 50000);
  std::vector<BandSystem> parts(chunks, BandSystem(nu, nv, p, q));
  parallel_chunks(n, chunks, [&](std::size_t b, std::size_t e, int c) {
    assemble_points(parts[c], points, u, v, du, dv, b, e);
  });
  BandSystem& sys = parts[0];
  for (int c = 1; c < chunks; ++c) sys.add(parts[c]);
  if (smoothing > 0.0) add_thin_plate(sys, du, dv, smoothing);

  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(free_count) * (p + 1) * (2 * q + 1));
  Eigen::MatrixX3d rhs(free_count, 3);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int r = unknown[i * nv + j];
      if (r < 0) continue;
      Eigen::Vector3d b = sys.rhs().col(i * nv + j);
      for (int di = -p; di <= p; ++di)
        for (int dj = -q; dj <= q; ++dj) {
          const int k = i + di, l = j + dj;
          if (k < 0 || k >= nu || l < 0 || l >= nv) continue;
          const double g = sys.at(i, j, di, dj);
          if (net.fixed[k * nv + l]) {
            b -= g * net.values.col(k * nv + l);
          } else if (unknown[k * nv + l] >= r && g != 0.0) {
            triplets.emplace_back(unknown[k * nv + l], r, g);  // lower triangle
          }
        }
      rhs.row(r) = b.transpose();
    }
  Eigen::SparseMatrix<double> A(free_count, free_count);
  A.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(A);
  Eigen::MatrixX3d x;
  if (free_count > 0) x = ldlt.solve(rhs);
  const double pivot_floor = 1e-14 * A.diagonal().cwiseAbs().maxCoeff();
  if (free_count > 0 && (ldlt.info() != Eigen::Success || !x.allFinite() ||
                         (ldlt.vectorD().array() <= pivot_floor).any()))
    throw NumericalError(
        "surface fit: the normal equations are singular (control points without data); "
        "add smoothing or use fewer control points");
  NurbsSurface::Points ctrl(nu * nv);
  for (int c = 0; c < nu * nv; ++c)
    ctrl[c] = net.fixed[c] ? Eigen::Vector3d(net.values.col(c))
                           : Eigen::Vector3d(x.row(unknown[c]).transpose());
  return NurbsSurface(p, q, du.knots, dv.knots, ctrl);
}

// Every point re-projected by local Newton from its current parameters (Hoschek correction).
struct Projection {
  Eigen::VectorXd u, v, distance;
  double max = 0.0, rms = 0.0;
};

Projection project_points(const NurbsSurface& s, const Eigen::Matrix3Xd& points,
                          const Eigen::VectorXd& u, const Eigen::VectorXd& v, int threads) {
  const SurfaceProjector projector(s);
  const std::size_t n = static_cast<std::size_t>(points.cols());
  Projection r{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  parallel_chunks(n, worker_count(threads, n, 2000), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t k = b; k < e; ++k) {
      const SurfaceProjection f = projector.project(points.col(k), u[k], v[k]);
      r.u[k] = f.u;
      r.v[k] = f.v;
      r.distance[k] = f.distance;
    }
  });
  if (n > 0) {
    r.max = r.distance.maxCoeff();
    r.rms = std::sqrt(r.distance.squaredNorm() / static_cast<double>(n));
  }
  return r;
}

// The midpoints of the spans (one direction) holding points beyond the tolerance, worst first,
// at most half the spans (at least one) and within max_count control points.
std::vector<double> worst_span_midpoints(const Direction& dir, const Eigen::VectorXd& t,
                                         const Eigen::VectorXd& distance, double tolerance,
                                         int max_count) {
  const int p = dir.degree, n = dir.size();
  std::vector<double> worst(n, 0.0);
  for (Eigen::Index k = 0; k < t.size(); ++k)
    if (distance[k] > tolerance) {
      const int s = find_span(p, dir.knots, n, t[k]);
      worst[s] = std::max(worst[s], distance[k]);
    }
  std::vector<int> spans;
  for (int s = p; s < n; ++s)
    if (worst[s] > 0.0 && dir.knots[s + 1] > dir.knots[s]) spans.push_back(s);
  std::sort(spans.begin(), spans.end(), [&](int a, int b) { return worst[a] > worst[b]; });
  const int limit = std::min<int>(
      {static_cast<int>(spans.size()), std::max(1, (n - p) / 2), std::max(0, max_count - n)});
  std::vector<double> mids;
  for (int k = 0; k < limit; ++k)
    mids.push_back(0.5 * (dir.knots[spans[k]] + dir.knots[spans[k] + 1]));
  std::sort(mids.begin(), mids.end());
  return mids;
}

void check_input(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                 const SurfaceFitOptions& o) {
  if (u.size() != points.cols() || v.size() != points.cols())
    throw InputError("surface fit: " + std::to_string(points.cols()) + " points but " +
                     std::to_string(u.size()) + " u and " + std::to_string(v.size()) +
                     " v parameters");
  if (!points.allFinite()) throw InputError("surface fit: a point has a non-finite coordinate");
  if (!((u.array() >= 0.0).all() && (u.array() <= 1.0).all() && (v.array() >= 0.0).all() &&
        (v.array() <= 1.0).all()))
    throw InputError("surface fit: parameters must lie in [0, 1]");
  if (o.degree_u < 1 || o.degree_v < 1 || o.degree_u > kMaxDegree || o.degree_v > kMaxDegree)
    throw InputError("surface fit: degrees must lie in [1, " + std::to_string(kMaxDegree) + "]");
  if (o.control_u < 0 || o.control_v < 0 || o.correction_rounds < 0 || o.smoothing < 0.0 ||
      o.tolerance < 0.0)
    throw InputError("surface fit: control counts, rounds, smoothing and tolerance must be >= 0");
}

}  // namespace

NurbsSurface least_squares_surface(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u,
                                   const Eigen::VectorXd& v, const SurfaceFitOptions& o) {
  check_input(points, u, v, o);
  std::optional<BoundaryPair> bu, bv;
  if (o.boundary) {
    bu = boundary_pair(o.boundary->u0, o.boundary->u1, o.degree_u, "u0", "u1");
    bv = boundary_pair(o.boundary->v0, o.boundary->v1, o.degree_v, "v0", "v1");
  }
  return solve_net(points, u, v, make_direction(o.degree_u, o.control_u, bu, "u"),
                   make_direction(o.degree_v, o.control_v, bv, "v"), o.smoothing, o.threads);
}

// Piegl & Tiller 2001, §2.3 and §4 (fixed-boundary LSQ, parameter correction); spec B2.
SurfaceFit fit_surface(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u,
                       const Eigen::VectorXd& v, const SurfaceFitOptions& options) {
  check_input(points, u, v, options);
  const SurfaceFitOptions& o = options;
  std::optional<BoundaryPair> bu, bv;
  if (o.boundary) {
    bu = boundary_pair(o.boundary->u0, o.boundary->u1, o.degree_u, "u0", "u1");
    bv = boundary_pair(o.boundary->v0, o.boundary->v1, o.degree_v, "v0", "v1");
  }
  Direction du = make_direction(o.degree_u, o.control_u, bu, "u");
  Direction dv = make_direction(o.degree_v, o.control_v, bv, "v");

  NurbsSurface surface = solve_net(points, u, v, du, dv, o.smoothing, o.threads);
  Projection proj = project_points(surface, points, u, v, o.threads);
  // Tolerance mode: knots in the worst spans until the max distance meets the tolerance.
  while (o.tolerance > 0.0 && proj.max > o.tolerance) {
    const std::vector<double> iu =
        worst_span_midpoints(du, u, proj.distance, o.tolerance, o.max_control_points);
    const std::vector<double> iv =
        worst_span_midpoints(dv, v, proj.distance, o.tolerance, o.max_control_points);
    if (iu.empty() && iv.empty()) break;
    Direction nu = du, nv = dv;
    nu.insert(iu);
    nv.insert(iv);
    try {
      surface = solve_net(points, u, v, nu, nv, o.smoothing, o.threads);
    } catch (const NumericalError&) {
      break;  // spans without enough data: keep the last solvable net
    }
    du = std::move(nu);
    dv = std::move(nv);
    proj = project_points(surface, points, u, v, o.threads);
  }

  SurfaceFit fit;
  fit.rounds.push_back({proj.max, proj.rms});
  NurbsSurface best_surface = surface;
  Projection best = proj;
  // Hoschek correction, over-relaxed: the next parameters are t + ω·(foot − t) with ω = 2 (plain
  // correction, ω = 1, gains ~8 % a round on doubly curved patches: the fit follows its own
  // parametrization); a round worse than the best by more than 1 % restarts from the best with ω
  // halved (down to 1); rounds end when plain correction gains less than 1 % or a round changes
  // nothing by 1 % either way. The best round is kept.
  Eigen::VectorXd tu = u, tv = v;  // the parameters the kept surface was fitted at
  double omega = 2.0;
  for (int r = 1; r <= o.correction_rounds; ++r) {
    const Eigen::VectorXd nu_ = (tu + omega * (best.u - tu)).cwiseMax(0.0).cwiseMin(1.0);
    const Eigen::VectorXd nv_ = (tv + omega * (best.v - tv)).cwiseMax(0.0).cwiseMin(1.0);
    surface = solve_net(points, nu_, nv_, du, dv, o.smoothing, o.threads);
    proj = project_points(surface, points, best.u, best.v, o.threads);
    fit.rounds.push_back({proj.max, proj.rms});
    if (proj.max < best.max) {
      const bool small_gain = !(proj.max < 0.99 * best.max);
      best = proj;
      best_surface = surface;
      fit.best_round = r;
      tu = nu_;
      tv = nv_;
      if (small_gain && omega == 1.0) break;
    } else {
      // No better, and not worse by 1 % either: the parameters have converged (noise floor).
      if (omega == 1.0 || proj.max <= 1.01 * best.max) break;
      omega = std::max(1.0, omega / 2);
    }
  }
  fit.surface = std::move(best_surface);
  fit.u = std::move(best.u);
  fit.v = std::move(best.v);
  fit.distances = std::move(best.distance);
  fit.max_distance = best.max;
  fit.rms_distance = best.rms;
  fit.tolerance_met = o.tolerance <= 0.0 || best.max <= o.tolerance;
  return fit;
}

}  // namespace polarform
