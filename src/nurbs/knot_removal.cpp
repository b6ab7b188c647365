#include "src/nurbs/knot_removal.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_insertion.h"
#include "src/nurbs/knot_remover.h"
#include "src/nurbs/knots.h"

namespace polarform {

namespace {

void check_tol(double tol, const char* what) {
  if (!(tol >= 0.0))
    throw InputError(std::string(what) + ": tolerance is " + to_text(tol) + ", expected >= 0");
}

// NURBS Book A5.8 for one knot, `times` removals at most.
KnotRemoval remove_knot(const BSpline& c, double u, int times, double tol, int point_dim,
                        const char* what) {
  check_tol(tol, what);
  if (!(u > c.front() && u < c.back()))
    throw InputError(std::string(what) + ": u = " + to_text(u) + " is not inside the domain (" +
                     to_text(c.front()) + ", " + to_text(c.back()) + ")");
  const int s = multiplicity(c.knots(), u);
  if (s == 0) throw InputError(std::string(what) + ": u = " + to_text(u) + " is not a knot");
  if (times < 1 || times > s)
    throw InputError(std::string(what) + ": times is " + std::to_string(times) + ", expected 1.." +
                     std::to_string(s) + " (the multiplicity of u = " + to_text(u) + ")");
  KnotRemover remover(c.degree(), c.knots(), c.coefs(), point_dim);
  const int removed = remover.remove(u, times, tol).removed;
  return {std::move(remover).finish(), removed};
}

// Every interior knot, left to right, as often as A5.8 lets it go within tol.
BSpline remove_removable_knots(const BSpline& c, double tol, int point_dim, const char* what) {
  check_tol(tol, what);
  KnotRemover remover(c.degree(), c.knots(), c.coefs(), point_dim);
  for (const Breakpoint& b : breakpoints(c.knots()))
    if (b.value > c.front() && b.value < c.back()) remover.remove(b.value, b.multiplicity, tol);
  return std::move(remover).finish();
}

// NURBS Book eq. (5.30) on homogeneous coefficients (last row the weights).
double homogeneous_tolerance(const Eigen::MatrixXd& h, double tol) {
  check_tol(tol, "homogeneous_tolerance");
  const Eigen::Index d = h.rows() - 1;
  if (d < 1)
    throw InputError("homogeneous_tolerance: expected coordinates and a weight row, got " +
                     std::to_string(h.rows()) + " row(s)");
  const double w_min = h.row(d).minCoeff();
  if (!(w_min > 0.0))
    throw InputError("homogeneous_tolerance: smallest weight is " + to_text(w_min) +
                     ", weights must be > 0");
  double p_max = 0.0;
  for (Eigen::Index i = 0; i < h.cols(); ++i)
    p_max = std::max(p_max, h.col(i).head(d).norm() / h(d, i));
  return tol * w_min / (1.0 + p_max);
}

}  // namespace

KnotRemoval remove_knot(const BSpline& c, double u, int times, double tol) {
  return remove_knot(c, u, times, tol, c.dim(), "remove_knot");
}

SurfaceKnotRemoval remove_knot_u(const BSplineSurface& s, double u, int times, double tol) {
  const KnotRemoval r = remove_knot(s.along_u(), u, times, tol, s.dim(), "remove_knot_u");
  return {BSplineSurface::from_along_u(r.spline, s.degree_v(), s.knots_v(), s.dim()), r.removed};
}

SurfaceKnotRemoval remove_knot_v(const BSplineSurface& s, double v, int times, double tol) {
  const KnotRemoval r = remove_knot(s.along_v(), v, times, tol, s.dim(), "remove_knot_v");
  return {BSplineSurface::from_along_v(r.spline, s.degree_u(), s.knots_u(), s.dim()), r.removed};
}

double homogeneous_tolerance(const BSpline& homogeneous, double tol) {
  return homogeneous_tolerance(homogeneous.coefs(), tol);
}

double homogeneous_tolerance(const BSplineSurface& homogeneous, double tol) {
  return homogeneous_tolerance(homogeneous.coefs(), tol);
}

BSpline remove_removable_knots(const BSpline& c, double tol) {
  return remove_removable_knots(c, tol, c.dim(), "remove_removable_knots");
}

BSplineSurface remove_removable_knots_u(const BSplineSurface& s, double tol) {
  return BSplineSurface::from_along_u(
      remove_removable_knots(s.along_u(), tol, s.dim(), "remove_removable_knots_u"), s.degree_v(),
      s.knots_v(), s.dim());
}

BSplineSurface remove_removable_knots_v(const BSplineSurface& s, double tol) {
  return BSplineSurface::from_along_v(
      remove_removable_knots(s.along_v(), tol, s.dim(), "remove_removable_knots_v"), s.degree_u(),
      s.knots_u(), s.dim());
}

LeastSquaresRemoval remove_knot_least_squares(const BSpline& c, double u, int point_dim) {
  const char* what = "remove_knot_least_squares";
  if (!(u > c.front() && u < c.back()))
    throw InputError(std::string(what) + ": u = " + to_text(u) + " is not inside the domain (" +
                     to_text(c.front()) + ", " + to_text(c.back()) + ")");
  if (multiplicity(c.knots(), u) != 1)
    throw InputError(std::string(what) + ": u = " + to_text(u) + " is not a simple knot");
  const int p = c.degree();
  const Knots& U = c.knots();
  const int r = static_cast<int>(std::find(U.begin(), U.end(), u) - U.begin());
  Knots reduced = U;
  reduced.erase(reduced.begin() + r);
  const Eigen::MatrixXd& Q = c.coefs();
  Eigen::MatrixXd P(Q.rows(), Q.cols() - 1);
  P.leftCols(r - p) = Q.leftCols(r - p);                  // P_i = Q_i, i < r − p
  P.rightCols(Q.cols() - r) = Q.rightCols(Q.cols() - r);  // P_i = Q_{i+1}, i >= r − 1
  // Unknowns x_k = P_{r−p+k}, k = 0..p−2; equation e = 0..p−1 is row i = r−p+e:
  // α_i x_{e} + (1 − α_i) x_{e−1} = Q_i, with x_{−1} = P_{r−p−1} and x_{p−1} = P_{r−1} known.
  const int m = p - 1;
  if (m > 0) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p, m);
    Eigen::MatrixXd rhs(p, Q.rows());
    for (int e = 0; e < p; ++e) {
      const int i = r - p + e;
      const double alpha =
          (u - reduced[static_cast<std::size_t>(i)]) /
          (reduced[static_cast<std::size_t>(i + p)] - reduced[static_cast<std::size_t>(i)]);
      rhs.row(e) = Q.col(i).transpose();
      if (e < m)
        A(e, e) = alpha;
      else
        rhs.row(e) -= alpha * P.col(r - 1).transpose();
      if (e > 0)
        A(e, e - 1) = 1 - alpha;
      else
        rhs.row(e) -= (1 - alpha) * P.col(r - p - 1).transpose();
    }
    const Eigen::MatrixXd x = (A.transpose() * A).ldlt().solve(A.transpose() * rhs);  // (8.28)
    for (int k = 0; k < m; ++k) P.col(r - p + k) = x.row(k).transpose();
  }
  LeastSquaresRemoval out{BSpline(p, reduced, P), 0.0};
  const BSpline back = insert_knot(out.spline, u, 1);
  const int d = point_dim > 0 ? point_dim : c.dim();
  if (c.dim() % d != 0)
    throw InputError(std::string(what) + ": point dimension " + std::to_string(d) +
                     " does not divide " + std::to_string(c.dim()));
  const Eigen::MatrixXd moved = back.coefs() - Q;
  for (int b = 0; b < c.dim(); b += d)
    out.bound = std::max(out.bound, moved.middleRows(b, d).colwise().norm().maxCoeff());
  return out;
}

}  // namespace polarform
