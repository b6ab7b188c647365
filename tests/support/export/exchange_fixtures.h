// Test geometry shared by the exchange tests: exact rational conics (circle, ellipse), Bezier
// degree elevation to build exact high-degree profiles, random rational closed and open curves of
// degree 3 / 9 / 12, an exact rational sphere octant (2,2), a rational (5,5) surface, a full
// sphere of revolution; plus sampling helpers and self-removing scratch directories.
#pragma once

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform::exchange_test {

// A fresh directory under the system temporary directory, removed with its files on destruction.
// Named per process: ctest runs each test of a suite as its own process, in parallel.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : dir_(std::filesystem::temp_directory_path() /
             ("polarform_exchange_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::filesystem::path operator/(const std::string& file) const { return dir_ / file; }

 private:
  std::filesystem::path dir_;
};

// Ellipse with semi-axes a (x) and b (y) around center, counter-clockwise from (cx + a, cy):
// four rational quadratic quarter arcs (NURBS Book §7.5), exact; a == b gives a circle.
inline NurbsCurve2d ellipse(double a, double b, Eigen::Vector2d center = Eigen::Vector2d::Zero()) {
  const double w = std::sqrt(0.5);
  const double xs[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, ys[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  NurbsCurve2d::Points p;
  std::vector<double> weights;
  for (int i = 0; i < 9; ++i) {
    p.push_back(center + Eigen::Vector2d(a * xs[i], b * ys[i]));
    weights.push_back(i % 2 ? w : 1.0);
  }
  return NurbsCurve2d(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, p, weights);
}

inline double binomial(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

// Exact degree elevation of a curve whose interior knots all have multiplicity = degree (a chain
// of Bezier segments): each segment elevated in homogeneous coordinates (NURBS Book eq. 5.36).
template <int Dim>
NurbsCurve<Dim> elevate_bezier_chain(const NurbsCurve<Dim>& c, int degree) {
  const int p = c.degree(), t = degree - p, segments = (c.size() - 1) / p;
  const Eigen::MatrixXd& P = c.homogeneous().coefs();
  Eigen::MatrixXd Q(P.rows(), segments * degree + 1);
  std::vector<double> interior;
  for (int s = 0; s < segments; ++s) {
    for (int i = 0; i <= degree; ++i) {
      Eigen::VectorXd q = Eigen::VectorXd::Zero(P.rows());
      for (int j = std::max(0, i - t); j <= std::min(p, i); ++j)
        q += binomial(p, j) * binomial(t, i - j) / binomial(degree, i) * P.col(s * p + j);
      Q.col(s * degree + i) = q;
    }
    if (s > 0) interior.insert(interior.end(), degree, c.knots()[p + s * p]);
  }
  return NurbsCurve<Dim>(BSpline(degree, clamped_knots(degree, c.front(), c.back(), interior), Q));
}

// Degree-9 closed rational curve around the origin: 14 control points on a wobbly circle
// (radius 30 +- 4), weights in [0.5, 2], last point repeating the first. With equal_end_weights
// false the last weight differs from the first (same closed point, different homogeneous point).
inline NurbsCurve2d closed_degree9(bool equal_end_weights = true) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> wobble(-4, 4), weight(0.5, 2.0);
  const int n = 14;
  NurbsCurve2d::Points p;
  std::vector<double> w;
  for (int i = 0; i < n - 1; ++i) {
    const double phi = 2 * std::numbers::pi * i / (n - 1), r = 30 + wobble(rng);
    p.emplace_back(r * std::cos(phi), r * std::sin(phi));
    w.push_back(weight(rng));
  }
  p.push_back(p.front());
  w.push_back(equal_end_weights ? w.front() : 1.7 * w.front());
  return NurbsCurve2d(9, uniform_clamped_knots(9, n - 9, 0.0, 1.0), p, w);
}

// Rational cubic with periodic (wrapped) structure: uniform knots 0..10, the last three homogeneous
// control points repeat the first three, so the curve is closed with C2 continuity on [3, 7].
inline NurbsCurve3d periodic_cubic() {
  Eigen::MatrixXd c(4, 7);
  c << 0, 5, 9, 4, 0, 5, 9,  //
      0, 7, -2, -6, 0, 7, -2,  //
      0, 2, 0, 1, 0, 2, 0,  //
      1, 2, 1, 1, 1, 2, 1;
  return NurbsCurve3d(BSpline(3, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, c));
}

// Open non-rational cubic in 3D with non-uniform knots.
inline NurbsCurve3d open_cubic() {
  NurbsCurve3d::Points p = {{0, 0, 0}, {10, 5, 1}, {20, -3, 4}, {30, 8, -2},
                            {40, 0, 6}, {55, 4, 3}, {60, -6, 0}, {72, 2, 5}};
  return NurbsCurve3d(3, clamped_knots(3, 0.0, 5.0, {0.5, 1.75, 2.0, 3.5}), p);
}

// Open rational degree-12 space curve, 17 control points on a helix-like path, parameter [2, 7].
inline NurbsCurve3d degree12() {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> weight(0.6, 1.6), jitter(-2, 2);
  NurbsCurve3d::Points p;
  std::vector<double> w;
  for (int i = 0; i < 17; ++i) {
    const double phi = 0.4 * i;
    p.emplace_back(40 * std::cos(phi) + jitter(rng), 40 * std::sin(phi) + jitter(rng), 3.0 * i);
    w.push_back(weight(rng));
  }
  return NurbsCurve3d(12, uniform_clamped_knots(12, 5, 2.0, 7.0), p, w);
}

// Exact sphere octant of radius r, degree (2,2): u along the meridian from the equator (x axis) to
// the pole (0,0,r), v around z from x to y. The row u = 1 collapses to the pole.
inline NurbsSurface sphere_octant(double r) {
  const double w = std::sqrt(0.5);
  const double mr[3] = {r, r, 0}, mz[3] = {0, r, r}, cx[3] = {1, 1, 0}, cy[3] = {0, 1, 1};
  const double wt[3] = {1, w, 1};
  NurbsSurface::Points p;
  std::vector<double> weights;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      p.emplace_back(mr[i] * cx[j], mr[i] * cy[j], mz[i]);
      weights.push_back(wt[i] * wt[j]);
    }
  return NurbsSurface(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, p, weights);
}

// Full sphere of radius r as one surface of revolution, degree (2,2): u is the meridian from the
// north pole to the south pole (two quarter arcs), v the full circle (four quarter arcs) around z.
// The normal S_u x S_v points outwards.
inline NurbsSurface sphere(double r) {
  const double w = std::sqrt(0.5);
  const double mr[5] = {0, r, r, r, 0}, mz[5] = {r, r, 0, -r, -r}, mw[5] = {1, w, 1, w, 1};
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  NurbsSurface::Points p;
  std::vector<double> weights;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 9; ++j) {
      p.emplace_back(mr[i] * cx[j], mr[i] * cy[j], mz[i]);
      weights.push_back(mw[i] * (j % 2 ? w : 1.0));
    }
  return NurbsSurface(2, 2, {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                      {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, p, weights);
}

// Rational (5,5) surface on [0, 2] x [1, 3]: 8 x 7 control net over a bumpy height field, weights
// in [0.5, 2], one interior knot of multiplicity 2 in u and one of multiplicity 1 in v.
inline NurbsSurface rational55() {
  std::mt19937 rng(55);
  std::uniform_real_distribution<double> height(-5, 5), weight(0.5, 2.0);
  NurbsSurface::Points p;
  std::vector<double> weights;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 7; ++j) {
      p.emplace_back(100 + 12.0 * i, -20 + 9.0 * j, height(rng));
      weights.push_back(weight(rng));
    }
  return NurbsSurface(5, 5, clamped_knots(5, 0.0, 2.0, {0.8, 0.8}), clamped_knots(5, 1.0, 3.0, {1.6}),
                      p, weights);
}

// x as "1.234e-15", for RecordProperty.
inline std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", x);
  return buf;
}

// n equally spaced parameters over [a, b], both ends included.
inline std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(a + (b - a) * i / (n - 1));
  return out;
}

}  // namespace polarform::exchange_test
