#include "designers/convert/degree_limited.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <cmath>
#include <string>

#include "designers/convert/conversion_error.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/periodic.h"

namespace polarform {

namespace {

constexpr int kMaxSpans = 20000;

// The spline space: uniform spans over R's domain, periodic (control values wrap) when R is closed.
struct Space {
  int degree, spans;
  bool periodic;
  double a, b;
  std::vector<double> breaks;
  Knots knots;
  int size;  // distinct control values

  Space(const PolarFunction& R, int p, int k)
      : degree(p), spans(k), periodic(R.closed()), a(R.start), b(R.end) {
    for (int i = 0; i <= k; ++i) breaks.push_back(i == k ? b : a + (b - a) * i / k);
    if (periodic) {
      knots = periodic_knots(p, breaks);
      size = k;
    } else {
      knots = clamped_knots(p, a, b, std::vector<double>(breaks.begin() + 1, breaks.end() - 1));
      size = k + p;
    }
  }

  // Adds the basis row of parameter t (weights into `row` of the triplets).
  void row(double t, int r, std::vector<Eigen::Triplet<double>>& triplets) const {
    const int n = static_cast<int>(knots.size()) - degree - 1;
    const int span = find_span(degree, knots, n, t);
    double N[kMaxDegree + 1];
    basis_funs(span, t, degree, knots, N);
    for (int j = 0; j <= degree; ++j) triplets.emplace_back(r, (span - degree + j) % size, N[j]);
  }

  // The clamped curve of the distinct control values (2 x size).
  NurbsCurve2d curve(const Eigen::MatrixXd& coefs) const {
    const BSpline plain = periodic ? clip(periodic_bspline(degree, breaks, coefs), a, b)
                                   : BSpline(degree, knots, coefs);
    Eigen::MatrixXd h(3, plain.size());
    h.topRows(2) = plain.coefs();
    h.row(2).setOnes();
    return NurbsCurve2d(BSpline(degree, plain.knots(), std::move(h)));
  }
};

Eigen::Vector2d profile_point(const PolarFunction& R, double psi) {
  return R(psi) * Eigen::Vector2d(std::cos(psi), std::sin(psi));
}

LimitedCurve measure(const Space& s, const PolarFunction& R, const Eigen::MatrixXd& coefs) {
  LimitedCurve out{s.curve(coefs), 0, 0, 0};
  const ProfileError e = profile_error(out.curve, R, s.a, s.b, 8 * s.spans);
  out.max_radial_error = e.max_radial;
  out.max_normal_error = e.max_normal;
  out.control_points = out.curve.size();
  return out;
}

// Least squares with `per_span` samples per span (solved by sparse Cholesky of the normal
// equations, a banded system).
LimitedCurve least_squares(const PolarFunction& R, int degree, int spans) {
  const Space s(R, degree, spans);
  const int per_span = degree + 2, m = spans * per_span;
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs(m, 2);
  for (int i = 0; i < m; ++i) {
    const double t = s.a + (s.b - s.a) * (i + 0.5) / m;
    s.row(t, i, triplets);
    rhs.row(i) = profile_point(R, t).transpose();
  }
  Eigen::SparseMatrix<double> A(m, s.size);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SparseMatrix<double> AtA = A.transpose() * A;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(AtA);
  if (solver.info() != Eigen::Success) throw NumericalError("degree-limited fit: singular system");
  const Eigen::MatrixXd coefs = solver.solve(A.transpose() * rhs).transpose();
  return measure(s, R, coefs);
}

// Interpolation at `points` parameters equally spaced in ψ (the spans' ends for open curves).
LimitedCurve interpolation(const PolarFunction& R, int degree, int points) {
  const bool periodic = R.closed();
  // Closed: as many control values as points. Open: points = spans + degree, samples spread so
  // that the Schoenberg–Whitney condition holds.
  const int spans = periodic ? points : points - degree;
  const Space s(R, degree, spans);
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs(points, 2);
  for (int i = 0; i < points; ++i) {
    // Even degrees interpolate at span middles, where the periodic system is not singular.
    const double shift = degree % 2 == 0 ? 0.5 : 0.0;
    const double t = periodic ? s.a + (s.b - s.a) * (i + shift) / points
                              : s.a + (s.b - s.a) * i / (points - 1);
    s.row(t, i, triplets);
    rhs.row(i) = profile_point(R, t).transpose();
  }
  Eigen::SparseMatrix<double> A(points, s.size);
  A.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) throw NumericalError("interpolation: singular system");
  return measure(s, R, solver.solve(rhs).transpose());
}

}  // namespace

LimitedCurve approximate_polar_curve(const PolarFunction& R, int degree, double tol) {
  if (degree < 1 || degree > kMaxDegree)
    throw InputError("degree-limited profile: degree " + std::to_string(degree) + " outside [1, " +
                     std::to_string(kMaxDegree) + "]");
  if (!(tol > 0)) throw InputError("degree-limited profile: tolerance must be > 0 mm");
  int spans = std::max(8, degree + 1);
  for (int round = 0; round < 30; ++round) {
    LimitedCurve c = least_squares(R, degree, spans);
    if (c.max_radial_error <= tol) return c;
    // The error falls like h^(p+1): aim 20 % below the tolerance.
    const double grow = std::pow(c.max_radial_error / (0.8 * tol), 1.0 / (degree + 1));
    spans = std::max(spans + 1, static_cast<int>(std::ceil(spans * grow)));
    if (spans > kMaxSpans) break;
  }
  throw NumericalError("degree-limited profile: no degree-" + std::to_string(degree) +
                       " spline with up to " + std::to_string(kMaxSpans) + " spans meets " +
                       number_text(tol) + " mm");
}

LimitedCurve interpolate_polar_curve(const PolarFunction& R, int degree, double tol) {
  if (!(tol > 0)) throw InputError("interpolation: tolerance must be > 0 mm");
  const int fewest = R.closed() ? degree + 1 : degree + 2;
  // Double until the tolerance is met, then bisect for the fewest points.
  int lo = fewest, hi = fewest;
  LimitedCurve best = interpolation(R, degree, hi);
  while (best.max_radial_error > tol) {
    lo = hi;
    hi *= 2;
    if (hi > kMaxSpans)
      throw NumericalError("interpolation: " + std::to_string(kMaxSpans) +
                           " points do not meet " + number_text(tol) + " mm");
    best = interpolation(R, degree, hi);
  }
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    LimitedCurve c = interpolation(R, degree, mid);
    if (c.max_radial_error <= tol)
      hi = mid, best = std::move(c);
    else
      lo = mid;
  }
  return best;
}

}  // namespace polarform
