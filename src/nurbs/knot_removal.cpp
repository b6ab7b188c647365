#include "src/nurbs/knot_removal.h"

#include <algorithm>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_remover.h"

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

}  // namespace polarform
