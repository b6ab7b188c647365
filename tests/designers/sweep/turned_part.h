// Synthetic turned parts for the sweep tests (spec §7.2 S1, S2): a stepped profile (cylinders, a
// cone, a groove, a fillet, flat ends reaching the axis) and a walled tube, revolved about a given
// axis as ring meshes (every profile vertex a ring of N vertices on the exact circle) or sampled
// scan-like (area-uniform, random azimuths, Gaussian noise).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "src/fit/rotation_axis.h"

namespace polarform::test {

// (z, r) vertices of the stepped profile, pole to pole; the fillet sampled at 4 interior points.
inline std::vector<Eigen::Vector2d> stepped_profile() {
  std::vector<Eigen::Vector2d> p{{0, 0},      {0, 0.3},    {0.4, 0.3},  {0.7, 0.45}, {1.0, 0.45},
                                 {1.0, 0.38}, {1.1, 0.38}, {1.1, 0.45}, {1.5, 0.45}};
  for (int k = 1; k <= 4; ++k) {  // fillet: quarter circle about (1.5, 0.40), radius 0.05
    const double t = k * std::numbers::pi / 2 / 5;
    p.emplace_back(1.5 + 0.05 * std::sin(t), 0.40 + 0.05 * std::cos(t));
  }
  p.insert(p.end(), {{1.55, 0.40}, {1.55, 0.25}, {2.0, 0.25}, {2.0, 0.0}});
  return p;
}

// The walled tube S2: inner radius 0.25, outer 0.4, length 1.2 (a closed rectangle).
inline std::vector<Eigen::Vector2d> tube_profile() {
  return {{0, 0.25}, {0, 0.4}, {1.2, 0.4}, {1.2, 0.25}};
}

// A vase wall S3: a foot on the axis, an outer skin r = 0.5 + 0.1 sin(πz) up to a rim at z = 2,
// the inner skin 0.05 inside it down to a floor at z = 0.1 that reaches the axis again: one open
// profile through both skins, pole to pole (polyline of 84 vertices).
inline std::vector<Eigen::Vector2d> vase_profile() {
  std::vector<Eigen::Vector2d> p{{0, 0}};
  for (int k = 0; k <= 40; ++k) {
    const double z = 2.0 * k / 40;
    p.emplace_back(z, 0.5 + 0.1 * std::sin(std::numbers::pi * z));
  }
  for (int k = 40; k >= 0; --k) {
    const double z = 0.1 + 1.9 * k / 40;
    p.emplace_back(z, 0.45 + 0.1 * std::sin(std::numbers::pi * z));
  }
  p.emplace_back(0.1, 0.0);
  return p;
}

inline AxisLine tilted_axis() {
  AxisLine a;
  a.direction =
      Eigen::AngleAxisd(0.5 * std::numbers::pi / 180, Eigen::Vector3d(1, 2, 0).normalized()) *
      Eigen::Vector3d(0.2, -0.3, 1).normalized();
  a.point = Eigen::Vector3d(3e-3, -2e-3, 1e-3) + Eigen::Vector3d(5, -7, 11);
  return a;
}

inline Eigen::Vector3d place(const AxisLine& axis, double z, double r, double theta) {
  const Eigen::Vector3d a = axis.direction;
  const Eigen::Vector3d e1 = a.unitOrthogonal(), e2 = a.cross(e1);
  return axis.point + z * a + r * (std::cos(theta) * e1 + std::sin(theta) * e2);
}

// Every profile vertex a ring of `segments` vertices (one vertex where r = 0).
inline Eigen::Matrix3Xd ring_mesh(const std::vector<Eigen::Vector2d>& profile, const AxisLine& axis,
                                  int segments) {
  std::vector<Eigen::Vector3d> v;
  for (const Eigen::Vector2d& q : profile) {
    if (q.y() == 0.0) {
      v.push_back(place(axis, q.x(), 0.0, 0.0));
      continue;
    }
    for (int s = 0; s < segments; ++s)
      v.push_back(place(axis, q.x(), q.y(), 2 * std::numbers::pi * s / segments + 0.1));
  }
  Eigen::Matrix3Xd P(3, static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) P.col(static_cast<Eigen::Index>(i)) = v[i];
  return P;
}

// A grooved bar as CAD tessellates it (mm): a flat end on the axis, a fillet of radius 2 (8
// segments) into a cylinder r = 20, a cone down to r = 12, a groove 2 deep and 5 wide, a cylinder,
// a flat end on the axis.
inline std::vector<Eigen::Vector2d> grooved_bar_profile() {
  std::vector<Eigen::Vector2d> p{{0, 0}, {0, 18}};
  for (int k = 1; k <= 8; ++k) {
    const double a = -std::numbers::pi / 2 + std::numbers::pi / 2 * k / 8;
    p.emplace_back(2 + 2 * std::sin(a), 18 + 2 * std::cos(a));
  }
  p.insert(p.end(),
           {{30, 20}, {40, 12}, {45, 12}, {45, 10}, {50, 10}, {50, 12}, {70, 12}, {70, 0}});
  return p;
}

// A tessellator's rings: each profile vertex a ring with as many segments as keep the chord
// error below `chord` (at least 8), each ring turned by its own phase, the vertices rounded to
// float32 as binary STL stores them (decimals = 0) or to `decimals` places as a text mesh does.
inline Eigen::Matrix3Xd tessellated_ring_mesh(const std::vector<Eigen::Vector2d>& profile,
                                              const AxisLine& axis, double chord,
                                              int decimals = 0) {
  std::vector<Eigen::Vector3d> v;
  const double scale = std::pow(10.0, decimals);
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const double z = profile[i].x(), r = profile[i].y();
    const int n =
        r == 0.0
            ? 1
            : std::max(8, static_cast<int>(std::ceil(std::numbers::pi / std::acos(1 - chord / r))));
    for (int s = 0; s < n; ++s) {
      const Eigen::Vector3d q =
          place(axis, z, r, 0.37 * static_cast<double>(i) + 2 * std::numbers::pi * s / n);
      v.push_back(decimals == 0 ? Eigen::Vector3d(q.cast<float>().cast<double>())
                                : Eigen::Vector3d((q * scale).array().round() / scale));
    }
  }
  Eigen::Matrix3Xd P(3, static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) P.col(static_cast<Eigen::Index>(i)) = v[i];
  return P;
}

// n area-uniform samples of the polygonal profile revolved (random azimuths); truth gets the
// noise-free points, the result has isotropic Gaussian noise sigma.
inline Eigen::Matrix3Xd scan_samples(const std::vector<Eigen::Vector2d>& profile,
                                     const AxisLine& axis, int n, double sigma, unsigned seed,
                                     Eigen::Matrix3Xd* truth = nullptr) {
  std::vector<double> cum{0.0};
  for (std::size_t i = 1; i < profile.size(); ++i)
    cum.push_back(cum.back() +
                  (profile[i] - profile[i - 1]).norm() * (profile[i].y() + profile[i - 1].y()) / 2);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, sigma);
  Eigen::Matrix3Xd P(3, n), T(3, n);
  for (int k = 0; k < n; ++k) {
    const double a = u(rng) * cum.back();
    const std::size_t i =
        static_cast<std::size_t>(std::upper_bound(cum.begin(), cum.end(), a) - cum.begin());
    const Eigen::Vector2d p0 = profile[i - 1], p1 = profile[i];
    // Within the segment, area-uniform: r linear in t, density ∝ r.
    double t = u(rng);
    const double r0 = p0.y(), r1 = p1.y();
    if (std::abs(r1 - r0) > 1e-12)
      t = (std::sqrt(r0 * r0 + t * (r1 * r1 - r0 * r0)) - r0) / (r1 - r0);
    const Eigen::Vector2d q = p0 + t * (p1 - p0);
    T.col(k) = place(axis, q.x(), q.y(), 2 * std::numbers::pi * u(rng));
    P.col(k) = T.col(k) + Eigen::Vector3d(g(rng), g(rng), g(rng));
  }
  if (truth) *truth = T;
  return P;
}

}  // namespace polarform::test
