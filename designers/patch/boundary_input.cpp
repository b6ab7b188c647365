#include "designers/patch/boundary_input.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/fit/curve_fit.h"
#include "src/number_text.h"

namespace polarform {

namespace {

Eigen::Vector3d first(const Eigen::Matrix3Xd& p) { return p.col(0); }
Eigen::Vector3d last(const Eigen::Matrix3Xd& p) { return p.col(p.cols() - 1); }

// Noise of a polyline from third differences: r_i = P_{i−1} − 3P_i + 3P_{i+1} − P_{i+2} has
// variance 20 σ² per coordinate for independent errors of σ and is blind to a quadratic trend, so a
// smooth curve sampled densely adds only |P‴|h³ (the second difference would add its curvature,
// |P″|h²).
double third_difference_noise(const Eigen::Matrix3Xd& p) {
  if (p.cols() < 4) return 0.0;
  double sum = 0.0;
  for (Eigen::Index i = 1; i + 2 < p.cols(); ++i)
    sum += (p.col(i - 1) - 3 * p.col(i) + 3 * p.col(i + 1) - p.col(i + 2)).squaredNorm();
  return std::sqrt(sum / (static_cast<double>(p.cols() - 3) * 3 * 20));
}

}  // namespace

FittedBoundary fit_boundary_polylines(const std::array<Eigen::Matrix3Xd, 4>& polylines,
                                      const BoundaryFitOptions& options) {
  for (int k = 0; k < 4; ++k)
    if (polylines[static_cast<std::size_t>(k)].cols() < 2)
      throw InputError("boundary curve " + std::to_string(k) + ": " +
                       std::to_string(polylines[static_cast<std::size_t>(k)].cols()) +
                       " point(s), expected at least 2");
  Eigen::Vector3d lo = polylines[0].rowwise().minCoeff(), hi = polylines[0].rowwise().maxCoeff();
  for (const Eigen::Matrix3Xd& p : polylines) {
    lo = lo.cwiseMin(p.rowwise().minCoeff());
    hi = hi.cwiseMax(p.rowwise().maxCoeff());
  }
  const double size = (hi - lo).norm();
  if (!(size > 0)) throw InputError("boundary: all boundary points coincide");
  FittedBoundary out;
  out.tolerance = options.tolerance > 0 ? options.tolerance : 1e-5 * size;
  out.corner_tolerance = options.corner_tolerance > 0 ? options.corner_tolerance : 0.01 * size;
  // Orientation: c0 as given or reversed, every later curve the way its nearer end continues the
  // loop; the choice of c0 with the smaller total gap wins.
  std::array<Eigen::Matrix3Xd, 4> best;
  double best_gap = INFINITY;
  for (const bool flip0 : {false, true}) {
    std::array<Eigen::Matrix3Xd, 4> c = polylines;
    std::array<bool, 4> rev{flip0, false, false, false};
    if (flip0) c[0] = c[0].rowwise().reverse().eval();
    for (std::size_t k = 1; k < 4; ++k) {
      const Eigen::Vector3d end = last(c[k - 1]);
      if ((last(c[k]) - end).norm() < (first(c[k]) - end).norm()) {
        c[k] = c[k].rowwise().reverse().eval();
        rev[k] = true;
      }
    }
    std::array<double, 4> gap{};
    double total = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      gap[k] = (first(c[k]) - last(c[(k + 3) % 4])).norm();
      total += gap[k];
    }
    if (total < best_gap) {
      best_gap = total;
      best = c;
      out.reversed = rev;
      out.corner_gap = gap;
    }
  }
  for (std::size_t k = 0; k < 4; ++k)
    if (out.corner_gap[k] > out.corner_tolerance)
      throw InputError(
          "boundary corner " + std::to_string(k) + " (where curve " + std::to_string(k) +
          " starts): the curves' ends are " + number_text(out.corner_gap[k]) +
          " mm apart, more than the corner tolerance " + number_text(out.corner_tolerance) +
          " mm; give the four curves in loop order, each starting where the previous "
          "ends");
  std::array<NurbsCurve3d, 4> curves;
  for (std::size_t k = 0; k < 4; ++k) {
    const Eigen::Matrix3Xd& p = best[k];
    CurveFitOptions<3> o;
    o.degree = std::clamp(static_cast<int>(p.cols()) - 1, 1, options.degree);
    o.start = 0.5 * (first(p) + last(best[(k + 3) % 4]));
    o.end = 0.5 * (last(p) + first(best[(k + 1) % 4]));
    out.noise[k] = third_difference_noise(p);
    o.tolerance = std::max(out.tolerance, 4.0 * out.noise[k]);
    o.max_control_points = std::max(o.degree + 1, static_cast<int>(p.cols()) / 4);
    const CurveFit<3> fit = fit_curve<3>(p, o);
    curves[k] = fit.curve;
    out.max_distance[k] = fit.max_distance;
    out.control_points[k] = fit.curve.size();
  }
  out.boundary = boundary_from_loop(curves, 1e-9 * size);
  return out;
}

StructuredGrid split_structured_grid(const Eigen::Matrix3Xd& points, int rows, int cols) {
  if (rows < 3 || cols < 3)
    throw InputError("--grid " + std::to_string(rows) + "," + std::to_string(cols) +
                     ": a structured grid needs at least 3 rows and 3 columns");
  if (static_cast<long long>(rows) * cols != points.cols())
    throw InputError("--grid " + std::to_string(rows) + "," + std::to_string(cols) + ": " +
                     std::to_string(static_cast<long long>(rows) * cols) +
                     " grid points, but the scan has " + std::to_string(points.cols()));
  const auto at = [&](int r, int c) { return points.col(static_cast<Eigen::Index>(r) * cols + c); };
  StructuredGrid g;
  g.polylines[0].resize(3, cols);
  g.polylines[2].resize(3, cols);
  for (int c = 0; c < cols; ++c) {
    g.polylines[0].col(c) = at(0, c);
    g.polylines[2].col(c) = at(rows - 1, cols - 1 - c);
  }
  g.polylines[1].resize(3, rows);
  g.polylines[3].resize(3, rows);
  for (int r = 0; r < rows; ++r) {
    g.polylines[1].col(r) = at(r, cols - 1);
    g.polylines[3].col(r) = at(rows - 1 - r, 0);
  }
  for (int r = 1; r + 1 < rows; ++r)
    for (int c = 1; c + 1 < cols; ++c) g.inside.push_back(r * cols + c);
  return g;
}

}  // namespace polarform
