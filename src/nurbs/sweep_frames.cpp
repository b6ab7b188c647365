#include "src/nurbs/sweep_frames.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"

namespace polarform {

namespace {

struct Jet {
  Eigen::Vector3d point, d1, d2;
};

Jet jet(const NurbsCurve3d& spine, double t) {
  const auto d = spine.derivatives(t, 2);
  if (!(d[1].norm() > 0.0))
    throw InputError("spine frames: the spine is not regular (C' = 0) at t = " + to_text(t));
  return {d[0], d[1], d[2]};
}

// The principal normal n = (C' × C″) × C' / |…| (MIT (8.41)), or nothing where C″ is parallel
// to C' to 1e-12 rad (κ = 0).
bool principal_normal(const Jet& j, Eigen::Vector3d& n) {
  const Eigen::Vector3d b = j.d1.cross(j.d2);
  if (!(b.norm() > 1e-12 * j.d1.norm() * j.d2.norm())) return false;
  n = b.cross(j.d1).normalized();
  return true;
}

// v − (v·T)T normalised; throws where v is parallel to T.
Eigen::Vector3d orthogonal_part(const Eigen::Vector3d& v, const Eigen::Vector3d& T, double t) {
  const Eigen::Vector3d x = v - v.dot(T) * T;
  if (!(x.norm() > 1e-9 * v.norm()))
    throw InputError("spine frames: the x direction is parallel to the tangent at t = " +
                     to_text(t));
  return x.normalized();
}

// The first x: the given one, else the principal normal, else the axis most orthogonal to T.
Eigen::Vector3d first_x(const Jet& j, const Eigen::Vector3d* initial_x, double t) {
  const Eigen::Vector3d T = j.d1.normalized();
  if (initial_x) return orthogonal_part(*initial_x, T, t);
  Eigen::Vector3d n;
  if (principal_normal(j, n)) return n;
  Eigen::Index k;
  T.cwiseAbs().minCoeff(&k);
  return orthogonal_part(Eigen::Vector3d::Unit(k), T, t);
}

// The unit normal of the plane of the control points, or nothing when they span no plane or
// more than one (collinear or not planar to 1e-12 of their size).
bool plane_normal(const NurbsCurve3d& spine, Eigen::Vector3d& normal) {
  const auto P = spine.control_points();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : P) mean += p;
  mean /= static_cast<double>(P.size());
  Eigen::MatrixXd A(P.size(), 3);
  for (std::size_t i = 0; i < P.size(); ++i) A.row(static_cast<Eigen::Index>(i)) = P[i] - mean;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const auto s = svd.singularValues();
  if (!(s(1) > 1e-12 * s(0)) || s(2) > 1e-12 * s(0)) return false;
  normal = svd.matrixV().col(2);
  return true;
}

SpineFrame make_frame(double t, const Jet& j, const Eigen::Vector3d& x) {
  const Eigen::Vector3d T = j.d1.normalized();
  const Eigen::Vector3d xo = orthogonal_part(x, T, t);
  return {t, j.point, T, xo, T.cross(xo)};
}

// Double reflection from (T0, r0) at x0 to the tangent T1 at x1; Wang, Jüttler, Zheng & Liu 2008,
// Algorithm 1.
Eigen::Vector3d double_reflection(const Eigen::Vector3d& x0, const Eigen::Vector3d& T0,
                                  const Eigen::Vector3d& r0, const Eigen::Vector3d& x1,
                                  const Eigen::Vector3d& T1) {
  const Eigen::Vector3d v1 = x1 - x0;
  const double c1 = v1.squaredNorm();
  if (c1 == 0.0) return r0;
  const Eigen::Vector3d rL = r0 - (2.0 / c1) * v1.dot(r0) * v1;
  const Eigen::Vector3d TL = T0 - (2.0 / c1) * v1.dot(T0) * v1;
  const Eigen::Vector3d v2 = T1 - TL;
  const double c2 = v2.squaredNorm();
  return c2 == 0.0 ? rL : Eigen::Vector3d(rL - (2.0 / c2) * v2.dot(rL) * v2);
}

// Sub-steps between two requested parameters: at least 64, and enough that the tangent turns by
// at most 2e-3 rad per step (the method's error is O(h⁴) in the turning per step).
int substeps(const NurbsCurve3d& spine, double a, double b) {
  constexpr int probe = 64;
  double turning = 0.0;
  Eigen::Vector3d previous = jet(spine, a).d1.normalized();
  for (int k = 1; k <= probe; ++k) {
    const Eigen::Vector3d T = jet(spine, a + (b - a) * k / probe).d1.normalized();
    turning += std::acos(std::clamp(previous.dot(T), -1.0, 1.0));
    previous = T;
  }
  return std::max(probe, static_cast<int>(std::ceil(turning / 2e-3)));
}

}  // namespace

// MIT 13.472J §8.3, Figs. 8.7–8.8 (Frenet, fixed); Wang et al. 2008 (rotation-minimising).
std::vector<SpineFrame> spine_frames(const NurbsCurve3d& spine, const std::vector<double>& ts,
                                     FrameRule rule, const Eigen::Vector3d* initial_x) {
  if (ts.empty()) throw InputError("spine frames: no parameters");
  for (std::size_t k = 0; k < ts.size(); ++k) {
    if (!(ts[k] >= spine.front() && ts[k] <= spine.back()))
      throw InputError("spine frames: t = " + to_text(ts[k]) + " outside the spine's domain [" +
                       to_text(spine.front()) + ", " + to_text(spine.back()) + "]");
    if (k > 0 && !(ts[k] > ts[k - 1]))
      throw InputError("spine frames: parameters must increase (t[" + std::to_string(k) +
                       "] = " + to_text(ts[k]) + ")");
  }
  std::vector<SpineFrame> out;
  out.reserve(ts.size());
  const Jet j0 = jet(spine, ts[0]);
  if (rule == FrameRule::frenet) {
    for (double t : ts) {
      const Jet j = jet(spine, t);
      Eigen::Vector3d n;
      if (!principal_normal(j, n))
        throw InputError(
            "spine frames: the Frenet frame is undefined where the curvature vanishes"
            " (t = " +
            to_text(t) + "); use the rmf or fixed rule");
      out.push_back(make_frame(t, j, n));
    }
    return out;
  }
  if (rule == FrameRule::fixed) {
    Eigen::Vector3d normal;
    const bool planar = !initial_x && plane_normal(spine, normal);
    const Eigen::Vector3d X = initial_x ? *initial_x : first_x(j0, nullptr, ts[0]);
    for (double t : ts) {
      const Jet j = jet(spine, t);
      // A planar spine keeps Y = the plane normal (x = Y × T); otherwise X stays constant.
      out.push_back(planar ? make_frame(t, j, normal.cross(j.d1.normalized()))
                           : make_frame(t, j, X));
    }
    if (planar && out.front().x.dot(X) < 0)
      for (auto& f : out) f.x = -f.x, f.y = -f.y;
    return out;
  }
  out.push_back(make_frame(ts[0], j0, first_x(j0, initial_x, ts[0])));
  for (std::size_t k = 1; k < ts.size(); ++k) {
    const double a = ts[k - 1], b = ts[k];
    const int m = substeps(spine, a, b);
    Eigen::Vector3d x0 = out.back().point, T0 = out.back().tangent, r = out.back().x;
    Jet j = j0;
    for (int s = 1; s <= m; ++s) {
      j = jet(spine, s == m ? b : a + (b - a) * s / m);
      const Eigen::Vector3d T1 = j.d1.normalized();
      r = double_reflection(x0, T0, r, j.point, T1);
      x0 = j.point;
      T0 = T1;
    }
    out.push_back(make_frame(b, j, r));
  }
  return out;
}

}  // namespace polarform
