#include "src/fit/pole_cap.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "src/error.h"
#include "src/nurbs/basis.h"

namespace polarform {

namespace {

using Vec3 = Eigen::Vector3d;
using Quintic = std::array<Vec3, 6>;

// Gram matrix of the cubic Bernstein basis on [0, 1]: ∫ B_a B_b = C(3,a) C(3,b) / (7 C(6,a+b)).
Eigen::Matrix4d cubic_bernstein_gram() {
  const double c3[4] = {1, 3, 3, 1}, c6[7] = {1, 6, 15, 20, 15, 6, 1};
  Eigen::Matrix4d G;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) G(a, b) = c3[a] * c3[b] / (7.0 * c6[a + b]);
  return G;
}

// A quintic whose control points are affine in (α, β): c_i = P_i + α Q_i + β R_i.
struct AffineQuintic {
  Quintic P, Q, R;
  Quintic at(double a, double b) const {
    Quintic c;
    for (int i = 0; i < 6; ++i) c[i] = P[i] + a * Q[i] + b * R[i];
    return c;
  }
};

// Bae 2002, eq. (D.6): the connecting curve between boundary data (S, S_u, S_uu) at v_j and v_opp.
AffineQuintic connecting(const Vec3 S[3], const Vec3 T[3]) {
  AffineQuintic c;
  for (auto* q : {&c.P, &c.Q, &c.R}) q->fill(Vec3::Zero());
  c.P[0] = S[0], c.P[1] = S[0], c.P[2] = S[0];
  c.Q[1] = S[1] / 5, c.Q[2] = 2 * S[1] / 5, c.R[2] = S[2] / 20;
  c.P[5] = T[0], c.P[4] = T[0], c.P[3] = T[0];
  c.Q[4] = T[1] / 5, c.Q[3] = 2 * T[1] / 5, c.R[3] = T[2] / 20;
  return c;
}

double bernstein5(int i, double t) {
  const double c[6] = {1, 5, 10, 10, 5, 1};
  return c[i] * std::pow(t, i) * std::pow(1 - t, 5 - i);
}

Vec3 midpoint(const Quintic& c) {
  Vec3 m = Vec3::Zero();
  for (int i = 0; i < 6; ++i) m += bernstein5(i, 0.5) * c[i];
  return m;
}

Vec3 mid_derivative(const Quintic& c) {
  const double b4[5] = {1, 4, 6, 4, 1};
  Vec3 d = Vec3::Zero();
  for (int i = 0; i < 5; ++i) d += 5.0 * b4[i] / 16.0 * (c[i + 1] - c[i]);
  return d;
}

// de Casteljau at t = 1/2: the halves [c(0) .. c(1/2)] and [c(1/2) .. c(1)].
std::pair<Quintic, Quintic> split(const Quintic& c) {
  Quintic front, rear, w = c;
  for (int r = 0; r <= 5; ++r) {
    front[r] = w[0];
    rear[5 - r] = w[5 - r];
    for (int i = 0; i < 5 - r; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
  }
  return {front, rear};
}

// Minimises ∫|C''|² over the third control point with the others fixed (Bae 2002, Step 3).
Vec3 fairest_third(const Quintic& q, const Eigen::Matrix4d& G) {
  Quintic z = q;
  z[2] = Vec3::Zero();
  const Eigen::Vector4d e(1, -2, 1, 0);  // how c_2 enters Δ²c_0..Δ²c_3
  Eigen::Matrix<double, 4, 3> r;
  for (int a = 0; a < 4; ++a) r.row(a) = (z[a] - 2 * z[a + 1] + z[a + 2]).transpose();
  return -(e.transpose() * G * r).transpose() / e.dot(G * e);
}

double line_angle(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), std::abs(a.dot(b)));
}

}  // namespace

// Bae 2002, §3.3.2 Steps 1–4 and Appendix D.2.
PoleCap build_pole_cap(const NurbsSurface& s, bool at_start) {
  const BSplineSurface& h = s.homogeneous();
  const int dv = s.degree_v(), nv = s.size_v();
  const Knots& V = s.knots_v();
  const double ub = at_start ? s.front_u() : s.back_u();
  const double period = s.back_v() - s.front_v();
  // Step 1: v-nodes (Greville abscissae) paired half a period apart.
  std::vector<double> g(nv);
  for (int j = 0; j < nv; ++j) {
    g[j] = 0.0;
    for (int k = 1; k <= dv; ++k) g[j] += V[j + k] / dv;
  }
  const int m = nv - 1, half = m / 2;
  bool symmetric = m % 2 == 0 && half >= 2 && (s.point(ub, s.front_v()) - s.point(ub, s.back_v())).norm() <=
                                                  1e-9 * s.point(ub, s.front_v()).norm();
  for (int j = 0; symmetric && j <= half; ++j)
    symmetric = std::abs(g[j + half] - g[j] - period / 2) <= 1e-9 * period;
  if (!symmetric)
    throw InputError("pole cap: the surface must be closed in v with nodes that pair half a period "
                     "apart (v-knots symmetric as in Bae 2002, eq. (3.15))");
  std::vector<std::array<Vec3, 3>> D(nv);  // S, S_u, S_uu at each node
  for (int j = 0; j < m; ++j) {
    const NurbsSurface::Points d = s.derivatives(ub, g[j], 2);
    D[j] = {d[0], d[3], d[6]};
  }
  std::vector<AffineQuintic> curves;
  for (int j = 0; j < half; ++j) curves.push_back(connecting(D[j].data(), D[j + half].data()));

  // Step 2: α*, β* minimising the spread of the midpoints (3.18), (D.10)-(D.11), plus 1e-6 of the
  // bending energy Σ_j ∫|C_j''|² (as squares through the Cholesky factor of the Bernstein Gram).
  const Eigen::Matrix4d G = cubic_bernstein_gram();
  const Eigen::Matrix4d L = G.llt().matrixL();
  Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
  Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
  auto add_square = [&](const Vec3& a, const Vec3& b, const Vec3& c, double w) {
    M(0, 0) += w * b.dot(b), M(0, 1) += w * b.dot(c), M(1, 1) += w * c.dot(c);
    rhs[0] -= w * a.dot(b), rhs[1] -= w * a.dot(c);
  };
  Vec3 mean[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  for (const auto& c : curves) {
    const Quintic* parts[3] = {&c.P, &c.Q, &c.R};
    for (int k = 0; k < 3; ++k) mean[k] += midpoint(*parts[k]) / half;
  }
  constexpr double kBendingWeight = 1e-6;
  for (const auto& c : curves) {
    add_square(midpoint(c.P) - mean[0], midpoint(c.Q) - mean[1], midpoint(c.R) - mean[2], 1.0);
    const Quintic* parts[3] = {&c.P, &c.Q, &c.R};
    for (int k = 0; k < 4; ++k) {  // C'' = 20 Σ B_{a,3} Δ²c_a, ∫|C''|² = Σ_k |Σ_a 20 L_ak Δ²c_a|²
      Vec3 y[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
      for (int a = 0; a < 4; ++a)
        for (int q = 0; q < 3; ++q)
          y[q] += 20.0 * L(a, k) * ((*parts[q])[a] - 2 * (*parts[q])[a + 1] + (*parts[q])[a + 2]);
      add_square(y[0], y[1], y[2], kBendingWeight);
    }
  }
  M(1, 0) = M(0, 1);
  const Eigen::Vector2d ab = M.ldlt().solve(rhs);
  PoleCap cap;
  cap.alpha = ab[0], cap.beta = ab[1];

  // p* (3.20) and n* (3.21).
  std::vector<Quintic> C;
  for (const auto& c : curves) C.push_back(c.at(cap.alpha, cap.beta));
  for (const auto& c : C) cap.point += midpoint(c) / half;
  Vec3 nsum = Vec3::Zero();
  double wsum = 0.0;
  for (int j = 0; j < half; ++j) {
    const Vec3 a = mid_derivative(C[j]);
    const Vec3 b = j + 1 < half ? mid_derivative(C[j + 1]) : Vec3(-mid_derivative(C[0]));
    const Vec3 n = a.cross(b);
    const double phi = std::atan2(n.norm(), a.dot(b));
    if (n.norm() > 0.0) nsum += phi * n.normalized(), wsum += phi;
  }
  if (!(wsum > 0.0) || !(nsum.norm() > 0.0))
    throw InputError("pole cap: the connecting curves have no common tangent plane");
  cap.normal = (nsum / wsum).normalized();
  if (cap.normal.dot(cap.point) < 0) cap.normal = -cap.normal;

  // Step 3: split, reverse the front halves, move the first three control points.
  std::vector<Quintic> half_curves(nv);
  for (int j = 0; j < half; ++j) {
    auto [front, rear] = split(C[j]);
    std::reverse(front.begin(), front.end());
    half_curves[j] = front;
    half_curves[j + half] = rear;
  }
  half_curves[m] = half_curves[0];  // the seam node v_e repeats v_s
  for (auto& q : half_curves) {
    q[0] = cap.point;
    q[1] -= cap.normal * cap.normal.dot(q[1] - cap.point);
    q[2] = fairest_third(q, G);
  }

  // Step 4: the cap interpolates the halves at the nodes, (3.22)-(3.24), in homogeneous form.
  Eigen::MatrixXd Nmat = Eigen::MatrixXd::Zero(nv, nv);
  double Nb[kMaxDegree + 1];
  for (int k = 0; k < nv; ++k) {
    const int span = find_span(dv, V, nv, g[k]);
    basis_funs(span, g[k], dv, V, Nb);
    for (int a = 0; a <= dv; ++a) Nmat(k, span - dv + a) = Nb[a];
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(Nmat);
  Eigen::MatrixXd coefs(4, 6 * nv);
  for (int i = 0; i < 6; ++i) {
    Eigen::MatrixXd rhs_i(nv, 4);
    for (int k = 0; k < nv; ++k) {
      double w4[4];
      h.point(ub, g[k], w4);
      rhs_i.row(k) << w4[3] * half_curves[k][i].transpose(), w4[3];
    }
    const Eigen::MatrixXd X = lu.solve(rhs_i);
    coefs.middleCols(i * nv, nv) = X.transpose();
  }
  cap.surface = NurbsSurface(BSplineSurface(5, dv, {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1}, V, std::move(coefs)));

  // Measured continuity: boundary coincidence, tangent planes along it, the pole.
  for (int a = 0; a <= 400; ++a) {
    const double v = s.front_v() + period * a / 400.0;
    cap.boundary_gap = std::max(cap.boundary_gap, (cap.surface.point(1.0, v) - s.point(ub, v)).norm());
    const Vec3 n1 = cap.surface.normal(1.0, v), n2 = s.normal(ub, v);
    if (n1.norm() > 0 && n2.norm() > 0) cap.boundary_normal_angle = std::max(cap.boundary_normal_angle, line_angle(n1, n2));
  }
  cap.pole = pole_continuity(cap.surface, true);
  return cap;
}

}  // namespace polarform
