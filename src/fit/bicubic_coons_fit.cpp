// Least-squares cross-boundary derivatives of a bicubically blended Coons patch (Piegl & Tiller
// 2001, §2.2; spec P2).
#include "src/fit/bicubic_coons_fit.h"

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "src/error.h"
#include "src/fit/constrained_least_squares.h"
#include "src/nurbs/common_basis.h"

namespace polarform {

namespace {

// A cross-derivative curve: the basis of the boundary curves it crosses, its end control points
// fixed to the boundary tangents, the others unknowns first .. first + size − 3.
struct Layout {
  int degree;
  Knots knots;
  int size;
  Eigen::Vector3d start, end;  // fixed end control points
  int first;                   // index of the first interior control point among the unknowns

  // The curve with unknowns X (rows) and the fixed ends scaled by `ends` (0: the linear part).
  NurbsCurve3d curve(const Eigen::MatrixX3d& X, double ends) const {
    NurbsCurve3d::Points P(size);
    P.front() = ends * start;
    P.back() = ends * end;
    for (int i = 1; i + 1 < size; ++i) P[i] = X.row(first + i - 1).transpose();
    return NurbsCurve3d(degree, knots, P);
  }
  // The first derivative at the start or end, an affine function coef·X + constant (NURBS Book
  // eq. (3.7)): p/(u_{p+1} − u_1)·(P_1 − P_0), p/(u_{n−1+p} − u_{n−1})·(P_{n−1} − P_{n−2}).
  void end_tangent(bool at_end, int unknowns, Eigen::RowVectorXd& coef,
                   Eigen::Vector3d& constant) const {
    const int n = size, p = degree;
    const double f = at_end ? p / (knots[n - 1 + p] - knots[n - 1]) : p / (knots[p + 1] - knots[1]);
    coef = Eigen::RowVectorXd::Zero(unknowns);
    constant = at_end ? Eigen::Vector3d(f * end) : Eigen::Vector3d(-f * start);
    const int inner = at_end ? n - 2 : 1;  // the neighbour of the fixed end
    const double sign = at_end ? -1.0 : 1.0;
    if (n == 2)
      constant += sign * f * (at_end ? start : end);
    else
      coef(first + inner - 1) = sign * f;
  }
};

Layout layout(const NurbsCurve3d& a, const NurbsCurve3d& b, const Eigen::Vector3d& start,
              const Eigen::Vector3d& end, int& unknowns) {
  const BSpline basis = common_basis({a.homogeneous(), b.homogeneous()});
  Layout l{basis.degree(), basis.knots(), basis.size(), start, end, unknowns};
  unknowns += l.size - 2;
  return l;
}

Eigen::Vector3d tangent(const NurbsCurve3d& c, double t) { return c.derivatives(t, 1)[1]; }

NurbsCurve3d zero_like(const NurbsCurve3d& c) {
  return NurbsCurve3d(c.degree(), c.knots(),
                      NurbsCurve3d::Points(c.size(), Eigen::Vector3d::Zero()));
}

double arc_length(const NurbsCurve3d& c) {
  double length = 0.0;
  for (int k = 1; k <= 1000; ++k)
    length += (c.point(k / 1000.0) - c.point((k - 1) / 1000.0)).norm();
  return length;
}

// P&T 2001, after Fig. 2: D̂ = (L/(L_u + L_v))·(L/mag)·D, mag the mean |D| over 101 parameters.
NurbsCurve3d scaled(const NurbsCurve3d& d, double L, double Lu, double Lv) {
  double mag = 0.0;
  for (int k = 0; k <= 100; ++k) mag += d.point(k / 100.0).norm() / 101.0;
  if (!(mag > 0.0)) return d;
  Eigen::MatrixXd P = d.homogeneous().coefs();
  P.topRows<3>() *= (L / (Lu + Lv)) * (L / mag);
  return NurbsCurve3d(BSpline(d.degree(), d.knots(), std::move(P)));
}

// max over the corners of |S_uv from dv'(u) − S_uv from du'(v)|.
double twist_mismatch(const CrossDerivatives& d) {
  double worst = 0.0;
  for (int a = 0; a <= 1; ++a)
    for (int c = 0; c <= 1; ++c)
      worst = std::max(
          worst, (tangent(c == 0 ? d.dv0 : d.dv1, a) - tangent(a == 0 ? d.du0 : d.du1, c)).norm());
  return worst;
}

}  // namespace

// Piegl & Tiller 2001, §2.2: the patch is affine in the interior control points X of the
// derivative curves, S(u, v) = S_0(u, v) + Σ_k c_k(u, v)·X_k; c_k by building the linear part
// with unit values (x, y, z carry three unknowns at once: the map acts coordinate-wise).
BicubicCoonsFit fit_bicubic_coons(const PatchBoundary& boundary, const Eigen::Matrix3Xd& points,
                                  const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                  const BicubicCoonsFitOptions& options) {
  const Eigen::Index N = points.cols();
  if (u.size() != N || v.size() != N)
    throw InputError("bicubic Coons fit: " + std::to_string(N) + " points but " +
                     std::to_string(u.size()) + " u and " + std::to_string(v.size()) +
                     " v parameters");
  const PatchBoundary& b = boundary;
  int unknowns = 0;
  const Layout dv0 = layout(b.u0, b.u1, tangent(b.v0, 0), tangent(b.v1, 0), unknowns);
  const Layout dv1 = layout(b.u0, b.u1, tangent(b.v0, 1), tangent(b.v1, 1), unknowns);
  const Layout du0 = layout(b.v0, b.v1, tangent(b.u0, 0), tangent(b.u1, 0), unknowns);
  const Layout du1 = layout(b.v0, b.v1, tangent(b.u0, 1), tangent(b.u1, 1), unknowns);

  // Twist compatibility at the corners (0,0), (1,0), (0,1), (1,1): dv_c'(a) = du_a'(c).
  const std::array<std::pair<const Layout*, bool>, 4> across_u{
      std::pair{&dv0, false}, std::pair{&dv0, true}, std::pair{&dv1, false}, std::pair{&dv1, true}};
  const std::array<std::pair<const Layout*, bool>, 4> across_v{
      std::pair{&du0, false}, std::pair{&du1, false}, std::pair{&du0, true}, std::pair{&du1, true}};
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<Eigen::RowVector3d> rhs;
  for (int k = 0; k < 4; ++k) {
    Eigen::RowVectorXd ca, cb;
    Eigen::Vector3d ka, kb;
    across_u[k].first->end_tangent(across_u[k].second, unknowns, ca, ka);
    across_v[k].first->end_tangent(across_v[k].second, unknowns, cb, kb);
    if ((ca - cb).isZero(0.0)) continue;  // no unknown involved: nothing to constrain
    rows.push_back(ca - cb);
    rhs.push_back((kb - ka).transpose());
  }
  Eigen::MatrixXd C(rows.size(), unknowns), D(rows.size(), 3);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    C.row(k) = rows[k];
    D.row(k) = rhs[k];
  }
  if (N + C.rows() < unknowns)
    throw InputError("bicubic Coons fit: " + std::to_string(N) + " points for " +
                     std::to_string(unknowns) + " unknown control points (" +
                     std::to_string(C.rows()) + " twist constraints)");

  const auto coons = [&](const PatchBoundary& pb, const Eigen::MatrixX3d& X, double ends) {
    return bicubic_coons(pb, CrossDerivatives{du0.curve(X, ends), du1.curve(X, ends),
                                              dv0.curve(X, ends), dv1.curve(X, ends)});
  };
  const PatchBoundary zero{zero_like(b.u0), zero_like(b.u1), zero_like(b.v0), zero_like(b.v1)};
  Eigen::MatrixXd A(N, unknowns), B(N, 3);
  const NurbsSurface s0 = coons(b, Eigen::MatrixX3d::Zero(unknowns, 3), 1.0);
  for (Eigen::Index j = 0; j < N; ++j)
    B.row(j) = (points.col(j) - s0.point(u(j), v(j))).transpose();
  for (int k = 0; k < unknowns; k += 3) {
    Eigen::MatrixX3d X = Eigen::MatrixX3d::Zero(unknowns, 3);
    const int count = std::min(3, unknowns - k);
    for (int c = 0; c < count; ++c) X(k + c, c) = 1.0;
    const NurbsSurface s = coons(zero, X, 0.0);
    for (Eigen::Index j = 0; j < N; ++j) {
      const Eigen::Vector3d p = s.point(u(j), v(j));
      for (int c = 0; c < count; ++c) A(j, k + c) = p(c);
    }
  }
  const Eigen::MatrixX3d X = constrained_least_squares(A, B, C, D);

  BicubicCoonsFit fit;
  fit.derivatives = {du0.curve(X, 1.0), du1.curve(X, 1.0), dv0.curve(X, 1.0), dv1.curve(X, 1.0)};
  if (options.scale_cross_derivatives) {
    const double Lu = 0.5 * (arc_length(b.u0) + arc_length(b.u1));
    const double Lv = 0.5 * (arc_length(b.v0) + arc_length(b.v1));
    CrossDerivatives& d = fit.derivatives;
    d = {scaled(d.du0, Lu, Lu, Lv), scaled(d.du1, Lu, Lu, Lv), scaled(d.dv0, Lv, Lu, Lv),
         scaled(d.dv1, Lv, Lu, Lv)};
  }
  fit.twist_mismatch = twist_mismatch(fit.derivatives);
  fit.surface = bicubic_coons(b, fit.derivatives);
  return fit;
}

}  // namespace polarform
