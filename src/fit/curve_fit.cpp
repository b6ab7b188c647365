// Parametric least-squares B-spline curve fit: the knot layout (runs between corners, periodic or
// clamped), the sparse normal equations with several right-hand sides, and the tolerance loop.
#include "src/fit/curve_fit.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/fit/curve_distance.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/knots.h"
#include "src/nurbs/periodic.h"

namespace polarform {

namespace {

// The shortest knot span the fit makes (the parameters live in [0, 1]).
constexpr double kMinSpan = 1e-9;

// Where the knots are: simple interior knots, corner knots of multiplicity p, and how the basis
// functions map to unknown control points (fixed ends, a closed curve joined at a corner, or
// periodic wrap-around).
struct Layout {
  int p = 3;
  bool periodic = false;  // smooth closed: periodic knots over breaks {0, simple…, 1}
  std::vector<double> simple, corners;
  std::vector<int> fixed;  // basis functions whose control point is given (sorted)

  Knots knots() const {
    if (periodic) {
      std::vector<double> breaks{0.0};
      breaks.insert(breaks.end(), simple.begin(), simple.end());
      breaks.push_back(1.0);
      return periodic_knots(p, breaks);
    }
    std::vector<double> interior = simple;
    for (double c : corners) interior.insert(interior.end(), p, c);
    std::sort(interior.begin(), interior.end());
    return clamped_knots(p, 0.0, 1.0, interior);
  }
  int basis_count() const {
    return periodic ? static_cast<int>(simple.size()) + 1 + p
                    : static_cast<int>(simple.size() + p * corners.size()) + p + 1;
  }
  // Distinct control points (a periodic curve repeats p of them).
  int distinct() const { return periodic ? static_cast<int>(simple.size()) + 1 : basis_count(); }
  int unknowns() const { return distinct() - static_cast<int>(fixed.size()); }
  // Unknown index of basis function j, or -1 - k for the k-th fixed one.
  int unknown(int j) const {
    if (periodic) return j % (static_cast<int>(simple.size()) + 1);
    const auto it = std::lower_bound(fixed.begin(), fixed.end(), j);
    if (it != fixed.end() && *it == j) return -1 - static_cast<int>(it - fixed.begin());
    return j - static_cast<int>(it - fixed.begin());
  }
  // The basis function that equals 1 at the corner knot c (multiplicity p, clamped knots).
  int corner_basis(double c) const {
    const Knots U = knots();
    return static_cast<int>(std::lower_bound(U.begin(), U.end(), c) - U.begin()) - 1;
  }
  // Distinct breaks 0 = b_0 < … < b_k = 1 (the spans).
  std::vector<double> breaks() const {
    std::vector<double> b{0.0};
    b.insert(b.end(), simple.begin(), simple.end());
    b.insert(b.end(), corners.begin(), corners.end());
    b.push_back(1.0);
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    return b;
  }
};

template <int Dim>
using Matrix = Eigen::Matrix<double, Dim, Eigen::Dynamic>;

// MIT eqs. (8.4)–(8.10): min Σ w_k |Σ_j N_j(u_k) P_j − Q_k|², fixed ends moved to the right-hand
// side (8.5); one sparse LDLᵀ of NᵀWN for all coordinates. Returns the control points per basis.
template <int Dim>
Matrix<Dim> solve_control_points(const Layout& L, const Knots& U, const Matrix<Dim>& Q,
                                 const Eigen::VectorXd& u, const Eigen::VectorXd& w,
                                 const Matrix<Dim>& fixed) {
  const int n = L.basis_count(), m = L.unknowns();
  const Eigen::Index N = Q.cols();
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(static_cast<std::size_t>(N) * (L.p + 1));
  Eigen::MatrixXd rhs(N, Dim);
  std::vector<double> basis(static_cast<std::size_t>(L.p) + 1);
  for (Eigen::Index k = 0; k < N; ++k) {
    const int span = find_span(L.p, U, n, u[k]);
    basis_funs(span, u[k], L.p, U, basis.data());
    const double sw = std::sqrt(w[k]);
    Eigen::Matrix<double, Dim, 1> r = Q.col(k);
    for (int a = 0; a <= L.p; ++a) {
      const int j = L.unknown(span - L.p + a);
      if (j < 0)
        r -= basis[a] * fixed.col(-1 - j);
      else
        trip.emplace_back(static_cast<int>(k), j, sw * basis[a]);
    }
    rhs.row(k) = sw * r.transpose();
  }
  Eigen::SparseMatrix<double> A(N, m);
  A.setFromTriplets(trip.begin(), trip.end());  // sums the wrapped (periodic) duplicates
  Eigen::SparseMatrix<double> M = A.transpose() * A;
  Eigen::MatrixXd B = A.transpose() * rhs;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(M);
  const double dmax = M.diagonal().maxCoeff();
  if (ldlt.info() != Eigen::Success || ldlt.vectorD().minCoeff() <= 1e-13 * dmax) {
    // Spans without data (Schoenberg–Whitney fails): a tiny fairness term λ Σ|P_{j−1} − 2P_j +
    // P_{j+1}|² makes the free control points of a run without data lie evenly on the line between
    // its fixed ones (a straight run stays straight).
    const double lambda = 1e-10 * dmax;
    std::vector<Eigen::Triplet<double>> d2;
    for (int j = 1; j + 1 < n; ++j) {
      const int col[3] = {L.unknown(j - 1), L.unknown(j), L.unknown(j + 1)};
      if (col[1] < 0) continue;  // not across a fixed (corner) control point
      const double c[3] = {1.0, -2.0, 1.0};
      Eigen::Matrix<double, Dim, 1> known = Eigen::Matrix<double, Dim, 1>::Zero();
      for (int a = 0; a < 3; ++a)
        if (col[a] < 0) known += c[a] * fixed.col(-1 - col[a]);
      for (int a = 0; a < 3; ++a) {
        if (col[a] < 0) continue;
        for (int b = 0; b < 3; ++b)
          if (col[b] >= 0) d2.emplace_back(col[a], col[b], lambda * c[a] * c[b]);
        B.row(col[a]) -= lambda * c[a] * known.transpose();
      }
    }
    Eigen::SparseMatrix<double> F(m, m);
    F.setFromTriplets(d2.begin(), d2.end());
    M += F;
    ldlt.compute(M);
    if (ldlt.info() != Eigen::Success)
      throw NumericalError("curve fit: the normal equations are singular");
  }
  const Eigen::MatrixXd X = ldlt.solve(B);
  Matrix<Dim> P(Dim, n);
  for (int j = 0; j < n; ++j) {
    const int q = L.unknown(j);
    P.col(j) = q < 0 ? Eigen::Matrix<double, Dim, 1>(fixed.col(-1 - q))
                     : Eigen::Matrix<double, Dim, 1>(X.row(q).transpose());
  }
  return P;
}

// NURBS Book eqs. (9.68)–(9.69) in spirit: `count` knots at equal numbers of data parameters
// strictly inside (a, b).
std::vector<double> equal_count_knots(std::vector<double> params, double a, double b, int count) {
  std::vector<double> out;
  if (count <= 0) return out;
  std::sort(params.begin(), params.end());
  const double margin = 1e-9 * (b - a);
  for (int j = 1; j <= count; ++j) {
    double k = a + (b - a) * j / (count + 1);
    if (params.size() >= 2) {
      const double f = static_cast<double>(j) / (count + 1) * (params.size() - 1);
      const std::size_t i = static_cast<std::size_t>(f);
      const double t = f - i;
      k = i + 1 < params.size() ? (1 - t) * params[i] + t * params[i + 1] : params.back();
    }
    if (k > a + margin && k < b - margin && (out.empty() || k > out.back() + margin))
      out.push_back(k);
  }
  return out;
}

template <int Dim>
struct CornerPoint {
  Eigen::Matrix<double, Dim, 1> point;
  bool after = true;  // the corner's data point lies on the leg after the corner
};

// The corner near point c: where the total-least-squares lines of up to k points on either side
// (c itself excluded, stopping at the curve ends) meet; for 3D lines, the midpoint of their
// common perpendicular. Nearly parallel legs keep the data point.
template <int Dim>
CornerPoint<Dim> refine_corner(const Matrix<Dim>& P, bool closed, int c, int k) {
  using Vec = Eigen::Matrix<double, Dim, 1>;
  const Eigen::Index n = P.cols();
  auto line = [&](int sign) {
    Vec mean = Vec::Zero();
    std::vector<Vec> pts;
    for (int j = 1; j <= k; ++j) {
      const Eigen::Index i = c + sign * j;
      if (!closed && (i < 0 || i >= n)) break;
      pts.push_back(P.col((i + n) % n));
      mean += pts.back();
    }
    if (pts.size() == 1) pts.push_back(P.col(c));  // one neighbour: the edge through c
    mean = Vec::Zero();
    for (const Vec& q : pts) mean += q;
    mean /= static_cast<double>(pts.size());
    Eigen::Matrix<double, Dim, Dim> C = Eigen::Matrix<double, Dim, Dim>::Zero();
    for (const Vec& q : pts) C += (q - mean) * (q - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, Dim, Dim>> es(C);
    return std::pair<Vec, Vec>{mean, es.eigenvectors().col(Dim - 1)};
  };
  const auto [a, d] = line(-1);
  const auto [b, e] = line(+1);
  CornerPoint<Dim> out{P.col(c), true};
  // Closest points a + s d, b + t e (NURBS-independent line–line formula).
  const double dd = d.dot(e), den = 1.0 - dd * dd;
  if (den > 1e-6) {
    const Vec r = a - b;
    const double s = (dd * e.dot(r) - d.dot(r)) / den, t = (e.dot(r) - dd * d.dot(r)) / den;
    out.point = 0.5 * (a + s * d + b + t * e);
  }
  auto dist = [&](const Vec& m, const Vec& dir) {
    const Vec r = P.col(c) - m;
    return (r - r.dot(dir) * dir).norm();
  };
  out.after = dist(b, e) <= dist(a, d);
  return out;
}

template <int Dim>
struct Round {
  Matrix<Dim> P;
  Knots U;
  Eigen::VectorXd distances, feet;
  double max = 0.0;
};

}  // namespace

// MIT eqs. (8.1)–(8.3).
template <int Dim>
Eigen::VectorXd chord_length_parameters(const Matrix<Dim>& points, bool closed) {
  const Eigen::Index n = points.cols();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 1; i < n; ++i) u[i] = u[i - 1] + (points.col(i) - points.col(i - 1)).norm();
  double total = n > 0 ? u[n - 1] : 0.0;
  if (closed && n > 1) total += (points.col(0) - points.col(n - 1)).norm();
  if (!(total > 0.0)) {
    for (Eigen::Index i = 0; i < n; ++i)
      u[i] = n > 1 ? static_cast<double>(i) / (closed ? n : n - 1) : 0.0;
    return u;
  }
  return u / total;
}

template <int Dim>
CurveFit<Dim> fit_curve(const Matrix<Dim>& input, const CurveFitOptions<Dim>& o) {
  using Point = Eigen::Matrix<double, Dim, 1>;
  const int p = o.degree;
  const Eigen::Index N = input.cols();
  if (p < 1 || p > 9)
    throw InputError("curve fit: degree " + std::to_string(p) + " outside [1, 9]");
  if (N < (o.closed ? 3 : p + 1))
    throw InputError("curve fit: " + std::to_string(N) + " points, need at least " +
                     std::to_string(o.closed ? 3 : p + 1));
  if (!input.allFinite()) throw InputError("curve fit: a point has a non-finite coordinate");
  if (o.weights.size() != 0 && o.weights.size() != N)
    throw InputError("curve fit: " + std::to_string(o.weights.size()) + " weights for " +
                     std::to_string(N) + " points");
  if (o.parameters.size() != 0 && o.parameters.size() != N)
    throw InputError("curve fit: " + std::to_string(o.parameters.size()) + " parameters for " +
                     std::to_string(N) + " points");
  for (int c : o.corners)
    if (c < 0 || c >= N)
      throw InputError("curve fit: corner index " + std::to_string(c) + " outside the points");

  // A corner is refined to the intersection of the regression lines of its neighbours on either
  // side (a polyline vertex stays where it is) and its control point is fixed there, so that the
  // runs between corners are fitted independently and straight runs come out exact.
  std::vector<int> corners = o.corners;
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  if (!o.closed)
    corners.erase(
        std::remove_if(corners.begin(), corners.end(), [&](int c) { return c == 0 || c == N - 1; }),
        corners.end());
  std::vector<CornerPoint<Dim>> refined;
  for (int c : corners) refined.push_back(refine_corner<Dim>(input, o.closed, c, o.corner_support));
  // Closed with corners: start at the first corner, whose refined point closes the curve.
  const Eigen::Index shift =
      !o.closed || refined.empty() ? 0 : (refined[0].after ? corners[0] : (corners[0] + 1) % N);
  Matrix<Dim> Q(Dim, N);
  const Eigen::VectorXd w = o.weights.size() ? o.weights : Eigen::VectorXd::Ones(N);
  Eigen::VectorXd wr(N);
  for (Eigen::Index k = 0; k < N; ++k) {
    Q.col(k) = input.col((k + shift) % N);
    wr[k] = w[(k + shift) % N];
  }
  Eigen::VectorXd u(N);
  const bool joined = o.closed && !refined.empty();
  if (o.parameters.size()) {
    for (Eigen::Index k = 0; k < N; ++k) u[k] = o.parameters[(k + shift) % N];
  } else if (joined) {  // chord lengths from the corner point around to it again
    Matrix<Dim> R(Dim, N + 1);
    R.col(0) = refined[0].point;
    R.rightCols(N) = Q;
    u = chord_length_parameters<Dim>(R, true).tail(N);
  } else {
    u = chord_length_parameters<Dim>(Q, o.closed);
  }

  Layout L;
  L.p = p;
  L.periodic = o.closed && refined.empty();
  std::vector<std::pair<double, Point>> fixed_at;  // (parameter, point) of fixed control points
  if (joined) {
    fixed_at.push_back({0.0, refined[0].point});
    fixed_at.push_back({1.0, refined[0].point});
  }
  if (!o.closed && (o.fix_ends || o.start))
    fixed_at.push_back({0.0, o.start ? *o.start : Point(Q.col(0))});
  if (!o.closed && (o.fix_ends || o.end))
    fixed_at.push_back({1.0, o.end ? *o.end : Point(Q.col(N - 1))});
  std::vector<int> corner_points;  // indices into Q at the corners: parameters kept
  for (std::size_t c = joined ? 1 : 0; c < refined.size(); ++c) {
    const Eigen::Index k = (corners[c] - shift + N) % N;
    // The corner lies between point k and its neighbour on the other leg.
    const Eigen::Index j = refined[c].after ? k - 1 : k + 1;
    double uc = u[k];
    if (j >= 0 && j < N) {
      const double a = (refined[c].point - Q.col(k)).norm(),
                   b = (refined[c].point - Q.col(j)).norm();
      if (a + b > 0.0) uc = u[k] + (u[j] - u[k]) * a / (a + b);
    }
    // Distinct from the ends and the other corners by more than a rounding error (given
    // parameters may pile up: the feet beyond an open curve's end all have u = 1).
    if (uc > kMinSpan && uc < 1 - kMinSpan &&
        std::none_of(L.corners.begin(), L.corners.end(),
                     [&](double c) { return std::abs(c - uc) <= kMinSpan; })) {
      L.corners.push_back(uc);
      fixed_at.push_back({uc, refined[c].point});
      corner_points.push_back(static_cast<int>(k));
    }
  }
  std::sort(L.corners.begin(), L.corners.end());
  std::sort(fixed_at.begin(), fixed_at.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  // Fixed control points by basis index; recomputed when knots are inserted.
  Matrix<Dim> fixed(Dim, static_cast<Eigen::Index>(fixed_at.size()));
  auto place_fixed = [&] {
    L.fixed.clear();
    for (std::size_t f = 0; f < fixed_at.size(); ++f) {
      const double t = fixed_at[f].first;
      L.fixed.push_back(t == 0.0 ? 0 : t == 1.0 ? L.basis_count() - 1 : L.corner_basis(t));
      fixed.col(static_cast<Eigen::Index>(f)) = fixed_at[f].second;
    }
  };
  place_fixed();

  // Initial simple knots: a count per run (between corners) by its share of the points.
  const std::vector<double> runs = L.breaks();
  const int base_unknowns = L.distinct();
  const int want = o.control_points > 0 ? o.control_points - base_unknowns
                                        : (L.periodic ? std::max(3, p + 1) - base_unknowns : 0);
  if (want < 0)
    throw InputError("curve fit: " + std::to_string(o.control_points) +
                     " control points are too few for degree " + std::to_string(p) + " and " +
                     std::to_string(L.corners.size()) + " corners (need " +
                     std::to_string(base_unknowns) + ")");
  auto params_in = [&](double a, double b) {
    std::vector<double> in;
    for (Eigen::Index k = 0; k < N; ++k)
      if (u[k] >= a && (u[k] < b || (b == 1.0 && u[k] <= b))) in.push_back(u[k]);
    return in;
  };
  for (std::size_t r = 0; r + 1 < runs.size() && want > 0; ++r) {
    const std::vector<double> in = params_in(runs[r], runs[r + 1]);
    const int share =
        r + 2 == runs.size()
            ? want - static_cast<int>(L.simple.size())
            : static_cast<int>(std::lround(static_cast<double>(want) * in.size() / N));
    const std::vector<double> k = equal_count_knots(in, runs[r], runs[r + 1], share);
    L.simple.insert(L.simple.end(), k.begin(), k.end());
  }
  std::erase_if(L.simple, [&](double k) {  // a simple knot on a corner would raise it above C0
    return std::any_of(L.corners.begin(), L.corners.end(),
                       [&](double c) { return std::abs(c - k) <= kMinSpan; });
  });
  std::sort(L.simple.begin(), L.simple.end());
  place_fixed();

  auto make_curve = [&](const Round<Dim>& rd) {
    BSpline b(p, rd.U, rd.P);
    if (L.periodic) b = clip(b, 0.0, 1.0);
    Eigen::MatrixXd h(Dim + 1, b.size());
    h.topRows(Dim) = b.coefs();
    h.row(Dim).setOnes();
    return NurbsCurve<Dim>(BSpline(p, b.knots(), h));
  };
  auto measure = [&](Round<Dim>& rd) {
    const NurbsCurve<Dim> c = make_curve(rd);
    const CurveDistance<Dim> dist(c, o.closed);
    rd.distances.resize(N);
    rd.feet.resize(N);
    rd.max = 0.0;
    for (Eigen::Index k = 0; k < N; ++k) {
      const auto f = dist.project(Q.col(k));
      rd.distances[k] = f.distance;
      rd.feet[k] = f.u;
      rd.max = std::max(rd.max, f.distance);
    }
  };
  auto solve = [&](const Eigen::VectorXd& params) {
    Round<Dim> rd;
    rd.U = L.knots();
    rd.P = solve_control_points<Dim>(L, rd.U, Q, params, wr, fixed);
    measure(rd);
    return rd;
  };

  const bool want_tol = o.control_points <= 0 && o.tolerance > 0.0;
  Round<Dim> best = solve(u);
  while (want_tol && best.max > o.tolerance) {
    // Split every span whose points miss the tolerance, at the median of its parameters.
    const std::vector<double> b = L.breaks();
    std::vector<double> add;
    for (std::size_t s = 0; s + 1 < b.size(); ++s) {
      std::vector<double> in;
      double worst = 0.0;
      for (Eigen::Index k = 0; k < N; ++k)
        if (u[k] >= b[s] && (u[k] < b[s + 1] || (s + 2 == b.size() && u[k] <= b[s + 1]))) {
          in.push_back(u[k]);
          worst = std::max(worst, best.distances[k]);
        }
      if (worst <= o.tolerance || b[s + 1] - b[s] <= 2 * kMinSpan) continue;
      const std::vector<double> k = equal_count_knots(in, b[s], b[s + 1], 1);
      add.push_back(k.empty() ? 0.5 * (b[s] + b[s + 1]) : k[0]);
    }
    if (add.empty() || L.distinct() + static_cast<int>(add.size()) > o.max_control_points) break;
    L.simple.insert(L.simple.end(), add.begin(), add.end());
    std::sort(L.simple.begin(), L.simple.end());
    place_fixed();
    best = solve(u);
  }
  // Hoschek's parameter correction: the feet become the parameters; corners stay on their knots.
  Eigen::VectorXd params = u;
  for (int r = 0; r < o.correction_rounds; ++r) {
    Eigen::VectorXd next = best.feet;
    if (o.closed) next = next.cwiseMax(0.0).cwiseMin(std::nextafter(1.0, 0.0));
    for (int k : corner_points) next[k] = params[k];
    if (!L.periodic) next[0] = u[0], next[N - 1] = u[N - 1];
    Round<Dim> rd = solve(next);
    if (!(rd.max < best.max)) break;
    best = std::move(rd);
    params = next;
  }

  CurveFit<Dim> out;
  out.curve = make_curve(best);
  out.parameters.resize(N);
  out.distances.resize(N);
  for (Eigen::Index k = 0; k < N; ++k) {
    out.parameters[(k + shift) % N] = params[k];
    out.distances[(k + shift) % N] = best.distances[k];
  }
  out.max_distance = best.max;
  out.rms = std::sqrt(best.distances.squaredNorm() / static_cast<double>(N));
  out.tolerance_met = !want_tol || best.max <= o.tolerance;
  out.corner_parameters = L.corners;
  if (joined) out.corner_parameters.insert(out.corner_parameters.begin(), 0.0);  // the C0 seam
  return out;
}

template Eigen::VectorXd chord_length_parameters<2>(const Matrix<2>&, bool);
template Eigen::VectorXd chord_length_parameters<3>(const Matrix<3>&, bool);
template CurveFit<2> fit_curve<2>(const Matrix<2>&, const CurveFitOptions<2>&);
template CurveFit<3> fit_curve<3>(const Matrix<3>&, const CurveFitOptions<3>&);

}  // namespace polarform
