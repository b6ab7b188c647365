// Test patches for the Coons and decomposition tests: a non-rational surface's four boundary
// curves and exact cross-boundary derivative curves, read off its control net (clamped knots:
// S_u(0, v) = p/(u_{p+1} − u_1)·(P_1j − P_0j), NURBS Book eq. (3.7) per column), and the control
// net's bounding-box diagonal.
#pragma once

#include <vector>

#include "src/nurbs/coons_surface.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform::test {

// Row j (a curve in u) or column i (a curve in v) of the net, scaled differences for derivatives.
inline NurbsCurve3d net_curve(const NurbsSurface& s, bool along_u, int fixed, int minus = -1,
                              double factor = 1.0) {
  const int n = along_u ? s.size_u() : s.size_v();
  NurbsCurve3d::Points P(n);
  for (int k = 0; k < n; ++k) {
    const auto at = [&](int f) { return along_u ? s.control_point(k, f) : s.control_point(f, k); };
    P[k] = minus < 0 ? at(fixed) : Eigen::Vector3d(factor * (at(fixed) - at(minus)));
  }
  return NurbsCurve3d(along_u ? s.degree_u() : s.degree_v(), along_u ? s.knots_u() : s.knots_v(),
                      P);
}

inline PatchBoundary surface_boundary(const NurbsSurface& s) {
  return {net_curve(s, true, 0), net_curve(s, true, s.size_v() - 1), net_curve(s, false, 0),
          net_curve(s, false, s.size_u() - 1)};
}

inline CrossDerivatives surface_cross_derivatives(const NurbsSurface& s) {
  const int p = s.degree_u(), q = s.degree_v(), n = s.size_u(), m = s.size_v();
  const Knots &U = s.knots_u(), &V = s.knots_v();
  return {net_curve(s, false, 1, 0, p / (U[p + 1] - U[1])),
          net_curve(s, false, n - 1, n - 2, p / (U[n - 1 + p] - U[n - 1])),
          net_curve(s, true, 1, 0, q / (V[q + 1] - V[1])),
          net_curve(s, true, m - 1, m - 2, q / (V[m - 1 + q] - V[m - 1]))};
}

inline double net_diagonal(const NurbsSurface& s) {
  Eigen::Vector3d lo = s.control_point(0, 0), hi = lo;
  for (int i = 0; i < s.size_u(); ++i)
    for (int j = 0; j < s.size_v(); ++j) {
      lo = lo.cwiseMin(s.control_point(i, j));
      hi = hi.cwiseMax(s.control_point(i, j));
    }
  return (hi - lo).norm();
}

// A bicubic Bezier patch on [0, 1]² from its 16 control points (index 4i + j, i along u).
inline NurbsSurface bezier_patch(const NurbsSurface::Points& P) {
  const Knots b{0, 0, 0, 0, 1, 1, 1, 1};
  return NurbsSurface(3, 3, b, b, P);
}

}  // namespace polarform::test
