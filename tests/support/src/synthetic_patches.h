// Synthetic scanned patches with their ground truth (spec §7.2): the bicubic patch set S8 — each a
// 4 × 4 Bézier net, so a bicubic fit can represent it exactly and what remains measures the
// parametrization — sampled at random parameters with its four exact boundary curves, and the
// structured 250° grid S9.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "src/nurbs/nurbs_surface.h"
#include "src/nurbs/patch_boundary.h"

namespace polarform::patch_test {

// S8: 'a' a quarter of a bulged surface of revolution (doubly curved), 'b' a thin strip long in u
// and curved tightly (120°) in v, 'c' a saddle, 'd' nearly straight boundaries with the interior
// control points lifted by 0.3·diag, 'e' the boundary u = 0 collapsed to a point.
inline NurbsSurface s8_patch(char id) {
  NurbsSurface::Points p(16);
  const auto at = [&](int i, int j) -> Eigen::Vector3d& { return p[static_cast<std::size_t>(i * 4 + j)]; };
  const double k = 4.0 / 3.0 * std::tan(std::numbers::pi / 8);  // quarter-circle handle
  const Eigen::Vector2d quarter[4] = {{1, 0}, {1, k}, {k, 1}, {0, 1}};
  const double alpha = 2 * std::numbers::pi / 3, h = 4.0 / 3.0 * std::tan(alpha / 4);
  const Eigen::Vector2d arc[4] = {{1, 0},
                                  {1, h},
                                  {std::cos(alpha) + h * std::sin(alpha), std::sin(alpha) - h * std::cos(alpha)},
                                  {std::cos(alpha), std::sin(alpha)}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double s = i / 3.0, t = j / 3.0;
      switch (id) {
        case 'a': {
          const double r[4] = {4, 5.5, 5.5, 4};
          at(i, j) = Eigen::Vector3d(r[i] * quarter[j].x(), r[i] * quarter[j].y(), 3.0 * i);
          break;
        }
        case 'b':
          at(i, j) = Eigen::Vector3d(20 * s, 1.0 * arc[j].x(), 1.0 * arc[j].y() + 0.5 * s * s);
          break;
        case 'c':
          at(i, j) = Eigen::Vector3d(10 * s, 10 * t, 6 * (s - 0.5) * (t - 0.5) * 4);
          break;
        case 'd': {
          const bool inside = i > 0 && i < 3 && j > 0 && j < 3;
          at(i, j) = Eigen::Vector3d(10 * s, 10 * t, 0.3 * std::sin(3 * s + t) +
                                                         (inside ? 0.3 * 10 * std::sqrt(2.0) : 0));
          break;
        }
        default: {  // 'e'
          const double r = 5 * s;
          at(i, j) = Eigen::Vector3d(r * quarter[j].x() + 0.5 * s * t, r * quarter[j].y(),
                                     4 * (1 - s) + 0.8 * s * t);
        }
      }
    }
  const Knots bezier{0, 0, 0, 0, 1, 1, 1, 1};
  return NurbsSurface(3, 3, bezier, bezier, p);
}

// The iso-curve S(·, v) (along_u) or S(u, ·) of a non-rational Bézier patch, exactly.
inline NurbsCurve3d iso_curve(const NurbsSurface& s, bool along_u, double at) {
  NurbsCurve3d::Points q(4);
  const double b[4] = {(1 - at) * (1 - at) * (1 - at), 3 * at * (1 - at) * (1 - at),
                       3 * at * at * (1 - at), at * at * at};
  for (int m = 0; m < 4; ++m) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n = 0; n < 4; ++n)
      c += b[n] * (along_u ? s.control_point(m, n) : s.control_point(n, m));
    q[static_cast<std::size_t>(m)] = c;
  }
  return NurbsCurve3d(3, Knots{0, 0, 0, 0, 1, 1, 1, 1}, q);
}

// The exact boundary of a Bézier patch (at = 0 or 1 only).
inline PatchBoundary exact_boundary(const NurbsSurface& s) {
  return PatchBoundary{iso_curve(s, true, 0), iso_curve(s, true, 1), iso_curve(s, false, 0),
                       iso_curve(s, false, 1)};
}

// Four polylines in loop order (c0 = S(u, 0), c1 = S(1, v), c2 = S(u, 1) backwards, c3 = S(0, v)
// backwards), `per_curve` points each.
inline std::array<Eigen::Matrix3Xd, 4> boundary_polylines(const NurbsSurface& s, int per_curve) {
  std::array<Eigen::Matrix3Xd, 4> out;
  for (auto& c : out) c.resize(3, per_curve);
  for (int k = 0; k < per_curve; ++k) {
    const double t = static_cast<double>(k) / (per_curve - 1);
    out[0].col(k) = s.point(t, 0);
    out[1].col(k) = s.point(1, t);
    out[2].col(k) = s.point(1 - t, 1);
    out[3].col(k) = s.point(0, 1 - t);
  }
  return out;
}

// A gently or strongly curved 8 × 8 bicubic patch on uniform knots over about 10 × 10 mm (the
// kind a NURBS model's faces are): a wavy height field, turned by `bend` radians about the v
// direction (0: gentle), rotated and moved rigidly.
inline NurbsSurface wavy_patch(double bend) {
  const Knots U{0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1, 1};
  NurbsSurface::Points p;
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const double x = 10.0 * i / 7, y = 10.0 * j / 7;
      const double z = 0.8 * std::sin(0.9 * x) * std::cos(0.6 * y) + 0.05 * x * y;
      const double a = bend * (x - 5) / 10;  // bent about an axis along y
      const double r = 10.0 / std::max(bend, 1e-9);
      const Eigen::Vector3d q =
          bend > 0 ? Eigen::Vector3d((r + z) * std::sin(a), y, (r + z) * std::cos(a) - r)
                   : Eigen::Vector3d(x, y, z);
      p.push_back(turn * q + Eigen::Vector3d(3, -7, 11));
    }
  return NurbsSurface(3, 3, U, U, p);
}

// The boundary of a clamped non-rational surface: its first and last rows and columns of control
// points on its knots, domains mapped to [0, 1].
inline PatchBoundary net_boundary(const NurbsSurface& s) {
  const auto curve = [&](bool along_u, int fixed) {
    NurbsCurve3d::Points q;
    const int n = along_u ? s.size_u() : s.size_v();
    for (int k = 0; k < n; ++k)
      q.push_back(along_u ? s.control_point(k, fixed) : s.control_point(fixed, k));
    return NurbsCurve3d(along_u ? s.degree_u() : s.degree_v(), along_u ? s.knots_u() : s.knots_v(),
                        q);
  };
  return PatchBoundary{curve(true, 0), curve(true, s.size_v() - 1), curve(false, 0),
                       curve(false, s.size_u() - 1)};
}

struct PatchSample {
  Eigen::Matrix3Xd points;
  Eigen::VectorXd u, v;  // true parameters
};

// n points at uniform random parameters strictly inside the domain, with normal noise of sigma
// along the surface normal.
inline PatchSample sample_patch(const NurbsSurface& s, int n, double sigma = 0.0,
                                unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(0.002, 0.998);
  std::normal_distribution<double> noise(0.0, 1.0);
  PatchSample out{Eigen::Matrix3Xd(3, n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int k = 0; k < n; ++k) {
    out.u[k] = uni(rng);
    out.v[k] = uni(rng);
    out.points.col(k) = s.point(out.u[k], out.v[k]);
    if (sigma > 0) out.points.col(k) += sigma * noise(rng) * s.normal(out.u[k], out.v[k]);
  }
  return out;
}

// S9: rows × cols points, row-major (row = a height slice, column = azimuth over 250°), on an
// ellipsoid with semi-axes 1, 0.8, 1.3 and a Gaussian bump, normal noise sigma (radial).
inline Eigen::Matrix3Xd s9_grid(int rows, int cols, double sigma, unsigned seed = 9) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::Matrix3Xd g(3, rows * cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const double z = -1.0 + 2.0 * r / (rows - 1);
      const double th = (250.0 * c / (cols - 1) - 125.0) * std::numbers::pi / 180;
      const double s = std::sqrt(1 - z * z / (1.3 * 1.3));
      const double bump = 0.15 * std::exp(-(th * th + z * z) / (2 * 0.3 * 0.3));
      const double rad = 1 + bump / s + sigma * noise(rng);
      g.col(r * cols + c) = Eigen::Vector3d(rad * s * std::cos(th), 0.8 * rad * s * std::sin(th), z);
    }
  return g;
}

}  // namespace polarform::patch_test
