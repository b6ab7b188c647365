#include "export/exchange_geometry.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

void require_exchangeable(int degree, const Knots& knots, std::string_view what) {
  if (degree < 1)
    throw InputError(std::string(what) + ": degree " + std::to_string(degree) +
                     ", exchange formats need degree >= 1");
  const std::vector<Breakpoint> b = breakpoints(knots);
  for (std::size_t i = 1; i + 1 < b.size(); ++i)
    if (b[i].multiplicity > degree)
      throw InputError(std::string(what) + ": interior knot " + std::to_string(b[i].value) +
                       " has multiplicity " + std::to_string(b[i].multiplicity) +
                       ", expected at most the degree " + std::to_string(degree) +
                       " (the spline may jump there; split it into pieces before export)");
}

NurbsCurve3d lift_to_3d(const NurbsCurve2d& curve) {
  const Eigen::MatrixXd& c2 = curve.homogeneous().coefs();
  Eigen::MatrixXd c3 = Eigen::MatrixXd::Zero(4, c2.cols());
  c3.topRows<2>() = c2.topRows<2>();
  c3.row(3) = c2.row(2);
  return NurbsCurve3d(BSpline(curve.degree(), curve.knots(), std::move(c3)));
}

NurbsCurve3d translated(const NurbsCurve3d& curve, const Eigen::Vector3d& offset) {
  Eigen::MatrixXd c = curve.homogeneous().coefs();
  c.topRows<3>() += offset * c.row(3);
  return NurbsCurve3d(BSpline(curve.degree(), curve.knots(), std::move(c)));
}

NurbsCurve3d iso_curve_at_u(const NurbsSurface& surface, double u) {
  const BSplineSurface& h = surface.homogeneous();
  const Eigen::VectorXd stacked = h.along_u().point(u);  // [Q_0; Q_1; ...], 4 rows each
  return NurbsCurve3d(BSpline(h.degree_v(), h.knots_v(), stacked.reshaped(4, h.size_v())));
}

NurbsCurve3d iso_curve_at_v(const NurbsSurface& surface, double v) {
  const BSplineSurface& h = surface.homogeneous();
  const Eigen::VectorXd stacked = h.along_v().point(v);
  return NurbsCurve3d(BSpline(h.degree_u(), h.knots_u(), stacked.reshaped(4, h.size_u())));
}

bool is_closed(const NurbsCurve3d& curve, double tolerance) {
  return (curve.point(curve.front()) - curve.point(curve.back())).norm() <= tolerance;
}

namespace {

// Largest distance between two curves on the same knot vector, sampled 8 times per span.
double sampled_distance(const NurbsCurve3d& a, const NurbsCurve3d& b) {
  double worst = 0.0;
  const Knots& k = a.knots();
  for (int s = a.degree(); s < a.size(); ++s) {
    if (k[s + 1] <= k[s]) continue;
    for (int t = 0; t <= 8; ++t) {
      const double u = k[s] + (k[s + 1] - k[s]) * t / 8.0;
      worst = std::max(worst, (a.point(u) - b.point(u)).norm());
    }
  }
  return worst;
}

}  // namespace

bool is_closed_u(const NurbsSurface& surface, double tolerance) {
  return sampled_distance(iso_curve_at_u(surface, surface.front_u()),
                          iso_curve_at_u(surface, surface.back_u())) <= tolerance;
}

bool is_closed_v(const NurbsSurface& surface, double tolerance) {
  return sampled_distance(iso_curve_at_v(surface, surface.front_v()),
                          iso_curve_at_v(surface, surface.back_v())) <= tolerance;
}

bool is_degenerate(const NurbsCurve3d& curve, double tolerance) {
  const Eigen::Vector3d first = curve.control_point(0);
  for (int i = 1; i < curve.size(); ++i)
    if ((curve.control_point(i) - first).norm() > tolerance) return false;
  return true;
}

bool has_periodic_structure(const BSpline& homogeneous) {
  const int p = homogeneous.degree(), n = homogeneous.size();
  if (p < 1 || n < 2 * p) return false;
  const Knots& U = homogeneous.knots();
  const double period = U[n] - U[p];
  const double knot_tol = 1e-12 * std::max({1.0, std::abs(U.front()), std::abs(U.back())});
  for (int i = 0; i <= 2 * p; ++i)
    if (std::abs(U[i + n - p] - U[i] - period) > knot_tol) return false;
  const Eigen::MatrixXd& c = homogeneous.coefs();
  const double coef_tol = 1e-12 * std::max(1.0, c.cwiseAbs().maxCoeff());
  for (int i = 0; i < p; ++i)
    if ((c.col(n - p + i) - c.col(i)).cwiseAbs().maxCoeff() > coef_tol) return false;
  return true;
}

std::optional<Eigen::Vector3d> plane_normal(const std::vector<Eigen::Vector3d>& points,
                                            double tolerance) {
  if (points.empty()) return Eigen::Vector3d::UnitZ();
  for (int axis : {2, 0, 1}) {
    const double c = points.front()[axis];
    if (std::all_of(points.begin(), points.end(),
                    [&](const Eigen::Vector3d& p) { return std::abs(p[axis] - c) <= tolerance; }))
      return Eigen::Vector3d::Unit(axis);
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - centroid) * (p - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  // Total least squares plane: the scatter matrix's eigenvector of the smallest eigenvalue.
  Eigen::Vector3d n = eig.eigenvectors().col(0).normalized();
  for (const auto& p : points)
    if (std::abs(n.dot(p - centroid)) > tolerance) return std::nullopt;
  Eigen::Index largest;
  n.cwiseAbs().maxCoeff(&largest);
  if (n[largest] < 0) n = -n;
  return n;
}

std::vector<Eigen::Vector3d> control_points_of(const NurbsCurve3d& curve) {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < curve.size(); ++i) out.push_back(curve.control_point(i));
  return out;
}

std::vector<Eigen::Vector3d> control_points_of(const NurbsSurface& surface) {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < surface.size_u(); ++i)
    for (int j = 0; j < surface.size_v(); ++j) out.push_back(surface.control_point(i, j));
  return out;
}

double max_abs_coordinate(const std::vector<Eigen::Vector3d>& points) {
  double m = 0.0;
  for (const auto& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
  return m;
}

}  // namespace polarform
