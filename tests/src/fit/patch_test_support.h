// Shared helpers of the patch tests (spec B2, P5–P7): random bicubic nets, exact boundary curves,
// cylinder-like patches and uniform blankets (the tensor grid of evaluated surface points, a valid
// crack-free blanket without a decomposition).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <random>

#include "src/nurbs/knots.h"
#include "src/nurbs/nurbs_surface.h"
#include "src/nurbs/patch_boundary.h"
#include "src/nurbs/surface_decomposition.h"

namespace polarform::test {

// A bicubic net of n × n on [0, 1]²: x, y on a jittered grid of side `size`, z random in ±size/5.
inline NurbsSurface random_bicubic(int n, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> J(-0.2, 0.2), Z(-size / 5, size / 5);
  NurbsSurface::Points P(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      P[i * n + j] =
          Eigen::Vector3d(size * (i + J(rng)) / (n - 1), size * (j + J(rng)) / (n - 1), Z(rng));
  const Knots K = uniform_clamped_knots(3, n - 3, 0.0, 1.0);
  return NurbsSurface(3, 3, K, K, P);
}

// The four boundary curves of a non-rational surface on [0, 1]² (its outer rows and columns).
inline PatchBoundary exact_boundary(const NurbsSurface& s) {
  const int nu = s.size_u(), nv = s.size_v();
  NurbsCurve3d::Points u0(nu), u1(nu), v0(nv), v1(nv);
  for (int i = 0; i < nu; ++i) u0[i] = s.control_point(i, 0), u1[i] = s.control_point(i, nv - 1);
  for (int j = 0; j < nv; ++j) v0[j] = s.control_point(0, j), v1[j] = s.control_point(nu - 1, j);
  return {NurbsCurve3d(s.degree_u(), s.knots_u(), u0), NurbsCurve3d(s.degree_u(), s.knots_u(), u1),
          NurbsCurve3d(s.degree_v(), s.knots_v(), v0), NurbsCurve3d(s.degree_v(), s.knots_v(), v1)};
}

// S8(a): a quarter of a bulged surface of revolution as one bicubic Bézier patch (radii 10, 14,
// 14, 10 at heights 0, 4, 8, 12; quarter circles with handle factor 0.5523).
inline NurbsSurface bulged_quarter() {
  const double k = 0.5523, r[4] = {10, 14, 14, 10}, z[4] = {0, 4, 8, 12};
  const Eigen::Vector2d arc[4] = {{1, 0}, {1, k}, {k, 1}, {0, 1}};
  NurbsSurface::Points P(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      P[i * 4 + j] = Eigen::Vector3d(r[j] * arc[i].x(), r[j] * arc[i].y(), z[j]);
  const Knots K = uniform_clamped_knots(3, 1, 0.0, 1.0);
  return NurbsSurface(3, 3, K, K, P);
}

// The bilinearly blended Coons patch of a bicubic Bézier patch's boundary (P&T §2.1), exactly:
// the linear blends degree-elevated to 3 have the coefficients 1 − i/3, i/3.
inline NurbsSurface bilinear_coons_of(const NurbsSurface& s) {
  NurbsSurface::Points C(16);
  const auto P = [&](int i, int j) { return s.control_point(i, j); };
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double a = i / 3.0, b = j / 3.0;
      C[i * 4 + j] = (1 - a) * P(0, j) + a * P(3, j) + (1 - b) * P(i, 0) + b * P(i, 3) -
                     ((1 - a) * (1 - b) * P(0, 0) + a * (1 - b) * P(3, 0) + (1 - a) * b * P(0, 3) +
                      a * b * P(3, 3));
    }
  return NurbsSurface(3, 3, s.knots_u(), s.knots_v(), C);
}

// A bicubic cylinder-like patch: control points on arcs of `degrees` (radius r) around z, n along
// the arc, 4 along z in [0, h]. At 360° the first and last columns coincide (a closed surface).
inline NurbsSurface cylinder_patch(double degrees, double r, double h, int n = 12) {
  NurbsSurface::Points P(n * 4);
  const double span = degrees * std::numbers::pi / 180.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 4; ++j) {
      const double a = span * i / (n - 1);
      P[i * 4 + j] = Eigen::Vector3d(r * std::cos(a), r * std::sin(a), h * j / 3.0);
    }
  return NurbsSurface(3, 3, uniform_clamped_knots(3, n - 3, 0.0, 1.0),
                      uniform_clamped_knots(3, 1, 0.0, 1.0), P);
}

// The tensor grid of S(u_a, v_b) for nu × nv uniform parameters on the domain.
inline SurfaceBlanket uniform_blanket(const NurbsSurface& s, int nu, int nv) {
  SurfaceBlanket b;
  for (int a = 0; a < nu; ++a)
    b.u.push_back(s.front_u() + (s.back_u() - s.front_u()) * a / (nu - 1));
  for (int c = 0; c < nv; ++c)
    b.v.push_back(s.front_v() + (s.back_v() - s.front_v()) * c / (nv - 1));
  b.points.resize(3, nu * nv);
  for (int a = 0; a < nu; ++a)
    for (int c = 0; c < nv; ++c) b.points.col(b.vertex(a, c)) = s.point(b.u[a], b.v[c]);
  return b;
}

// n points S(u, v) at uniform random parameters, with the parameters.
struct Samples {
  Eigen::Matrix3Xd points;
  Eigen::VectorXd u, v;
};
inline Samples sample_surface(const NurbsSurface& s, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Samples out{Eigen::Matrix3Xd(3, n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int k = 0; k < n; ++k) {
    out.u[k] = U(rng);
    out.v[k] = U(rng);
    out.points.col(k) = s.point(out.u[k], out.v[k]);
  }
  return out;
}

}  // namespace polarform::test
