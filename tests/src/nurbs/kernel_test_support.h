// Shared builders for the kernel algorithm tests: random knot vectors and B-splines, the rational
// quadratic (RQB) circle and base sphere / cylinder, and dense-sampling deviation measures.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform::test {

// A measured number for RecordProperty (visible in --gtest_output=xml), three significant digits.
inline std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

// A clamped knot vector on [a, b] with `count` random interior values of random multiplicity
// 1..max_mult, plus the listed extra values (each with multiplicity extra_mult).
inline Knots random_knots(std::mt19937& rng, int degree, double a, double b, int count,
                          int max_mult, const std::vector<double>& extra = {}, int extra_mult = 1) {
  std::uniform_real_distribution<double> t(a, b);
  std::uniform_int_distribution<int> mult(1, std::max(1, max_mult));
  std::vector<double> interior;
  for (int i = 0; i < count; ++i) {
    const double v = a + (b - a) * (0.05 + 0.9 * (t(rng) - a) / (b - a));
    interior.insert(interior.end(), max_mult > 0 ? mult(rng) : 0, v);
  }
  for (double v : extra) interior.insert(interior.end(), extra_mult, v);
  std::sort(interior.begin(), interior.end());
  Knots U(degree + 1, a);
  U.insert(U.end(), interior.begin(), interior.end());
  U.insert(U.end(), degree + 1, b);
  return U;
}

inline Eigen::MatrixXd random_coefs(std::mt19937& rng, int dim, int n, double lo = -1.0,
                                    double hi = 1.0) {
  std::uniform_real_distribution<double> c(lo, hi);
  Eigen::MatrixXd P(dim, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < dim; ++i) P(i, j) = c(rng);
  return P;
}

inline BSpline random_bspline(std::mt19937& rng, int degree, Knots U, int dim) {
  const int n = static_cast<int>(U.size()) - degree - 1;
  return BSpline(degree, std::move(U), random_coefs(rng, dim, n));
}

// A homogeneous B-spline with random positive weights in [0.5, 2] (last row).
inline BSpline random_rational(std::mt19937& rng, int degree, Knots U, int dim) {
  BSpline c = random_bspline(rng, degree, std::move(U), dim + 1);
  Eigen::MatrixXd P = c.coefs();
  const Eigen::MatrixXd w = random_coefs(rng, 1, c.size(), 0.5, 2.0);
  for (int j = 0; j < c.size(); ++j) {
    P.col(j).head(dim) *= w(0, j);
    P(dim, j) = w(0, j);
  }
  return BSpline(degree, c.knots(), P);
}

// Largest |a(u) - b(u)| over `samples` uniform parameters plus the knots of a, after projecting
// homogeneous points to Cartesian when `rational`.
inline double max_deviation(const BSpline& a, const BSpline& b, int samples, bool rational) {
  std::vector<double> us;
  for (int k = 0; k <= samples; ++k) us.push_back(a.front() + (a.back() - a.front()) * k / samples);
  for (double k : a.knots())
    if (k >= a.front() && k <= a.back()) us.push_back(k);
  double worst = 0.0;
  for (double u : us) {
    Eigen::VectorXd pa = a.point(u), pb = b.point(u);
    if (rational) {
      const Eigen::Index d = pa.size() - 1;
      pa = (pa.head(d) / pa(d)).eval();
      pb = (pb.head(d) / pb(d)).eval();
    }
    worst = std::max(worst, (pa - pb).norm());
  }
  return worst;
}

inline double max_deviation(const BSplineSurface& a, const BSplineSurface& b, int samples) {
  double worst = 0.0;
  for (int i = 0; i <= samples; ++i)
    for (int j = 0; j <= samples; ++j) {
      const double u = a.front_u() + (a.back_u() - a.front_u()) * i / samples;
      const double v = a.front_v() + (a.back_v() - a.front_v()) * j / samples;
      worst = std::max(worst, (a.point(u, v) - b.point(u, v)).norm());
    }
  return worst;
}

// Homogeneous control values of an RQB circle of radius r through 4 arcs of 90°, parameter = angle
// (knots 0, π/2, π, 3π/2, 2π, each interior one double): 9 columns (w·x, w·y, w).
inline Eigen::MatrixXd rqb_circle_coefs(double r) {
  const double w = std::sqrt(0.5);
  const double pts[9][3] = {{1, 0, 1},   {1, 1, w},  {0, 1, 1},  {-1, 1, w}, {-1, 0, 1},
                            {-1, -1, w}, {0, -1, 1}, {1, -1, w}, {1, 0, 1}};
  Eigen::MatrixXd h(3, 9);
  for (int i = 0; i < 9; ++i)
    h.col(i) << r * pts[i][0] * pts[i][2], r * pts[i][1] * pts[i][2], pts[i][2];
  return h;
}

inline Knots rqb_circle_knots() {
  const double q = std::numbers::pi / 2;
  return {0, 0, 0, q, q, 2 * q, 2 * q, 3 * q, 3 * q, 4 * q, 4 * q, 4 * q};
}

inline NurbsCurve2d rqb_circle(double r) {
  return NurbsCurve2d(BSpline(2, rqb_circle_knots(), rqb_circle_coefs(r)));
}

// Unit base sphere (2, 2): u the meridian from the south pole (u = -π/2) to the north pole
// (u = π/2) in two 90° RQB arcs, v the equator circle as in rqb_circle (angle parameters).
inline NurbsSurface base_sphere() {
  const double w = std::sqrt(0.5), q = std::numbers::pi / 2;
  const double mer[5][3] = {{0, -1, 1}, {1, -1, w}, {1, 0, 1}, {1, 1, w}, {0, 1, 1}};  // (r, z, w)
  const Eigen::MatrixXd circle = rqb_circle_coefs(1.0);
  Eigen::MatrixXd h(4, 5 * 9);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 9; ++j) {
      const double wv = circle(2, j), wu = mer[i][2];
      h.col(i * 9 + j) << mer[i][0] * circle(0, j) * wu, mer[i][0] * circle(1, j) * wu,
          mer[i][1] * wv * wu, wu * wv;
    }
  return NurbsSurface(BSplineSurface(2, 2, {-q, -q, -q, 0, 0, q, q, q}, rqb_circle_knots(), h));
}

// Base cylinder (1, 2): radius 1, u = z in [z0, z1] linear, v the circle as in rqb_circle.
inline NurbsSurface base_cylinder(double z0, double z1) {
  const Eigen::MatrixXd circle = rqb_circle_coefs(1.0);
  Eigen::MatrixXd h(4, 2 * 9);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 9; ++j) {
      const double z = i == 0 ? z0 : z1, wv = circle(2, j);
      h.col(i * 9 + j) << circle(0, j), circle(1, j), z * wv, wv;
    }
  return NurbsSurface(BSplineSurface(1, 2, {z0, z0, z1, z1}, rqb_circle_knots(), h));
}

}  // namespace polarform::test
