#include "src/fit/product_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "src/base/base_circle.h"
#include "src/base/base_cylinder.h"
#include "src/base/base_sphere.h"
#include "src/error.h"
#include "src/nurbs/basis.h"

namespace polarform {

namespace {

constexpr int kMaxIterations = 30;

// The p+1 non-zero basis functions at u into d[0..p] and their first derivatives into
// d[p+1..2p+1], the latter from the degree p−1 functions; NURBS Book eq. (2.9).
void basis_and_derivative(int span, double u, int p, const Knots& U, double* d) {
  basis_funs(span, u, p, U, d);
  double* dN = d + p + 1;
  if (p == 0) {
    dN[0] = 0.0;
    return;
  }
  double M[kMaxDegree + 1];  // N_{span-p+1 .. span, p-1}
  basis_funs(span, u, p - 1, U, M);
  for (int j = 0; j <= p; ++j) {
    const int i = span - p + j;
    double x = 0.0;
    if (j >= 1 && U[i + p] > U[i]) x += M[j - 1] / (U[i + p] - U[i]);
    if (j < p && U[i + p + 1] > U[i + 1]) x -= M[j] / (U[i + p + 1] - U[i + 1]);
    dN[j] = p * x;
  }
}

// F, F_u, F_v of a scalar tensor-product B-spline; NURBS Book A3.5 with first derivatives.
void scalar_and_partials(const BSplineSurface& F, double u, double v, double* out) {
  const int pu = F.degree_u(), pv = F.degree_v(), nu = F.size_u(), nv = F.size_v();
  const int su = find_span(pu, F.knots_u(), nu, u), sv = find_span(pv, F.knots_v(), nv, v);
  double du[2 * (kMaxDegree + 1)], dv[2 * (kMaxDegree + 1)];
  basis_and_derivative(su, u, pu, F.knots_u(), du);
  basis_and_derivative(sv, v, pv, F.knots_v(), dv);
  const double* c = F.coefs().data();
  double f = 0.0, fu = 0.0, fv = 0.0;
  for (int a = 0; a <= pu; ++a) {
    const double* row = c + (su - pu + a) * nv + (sv - pv);
    double s0 = 0.0, s1 = 0.0;
    for (int b = 0; b <= pv; ++b) s0 += dv[b] * row[b], s1 += dv[pv + 1 + b] * row[b];
    f += du[a] * s0;
    fu += du[pu + 1 + a] * s0;
    fv += du[a] * s1;
  }
  out[0] = f, out[1] = fu, out[2] = fv;
}

}  // namespace

void rational_point_and_derivative(const BSpline& h, double u, double* out) {
  const int p = h.degree(), n = h.size();
  const int span = find_span(p, h.knots(), n, u);
  double d[2 * (kMaxDegree + 1)];
  basis_and_derivative(span, u, p, h.knots(), d);
  double A[3] = {0, 0, 0}, Ad[3] = {0, 0, 0};
  for (int j = 0; j <= p; ++j) {
    const double* c = h.coefs().col(span - p + j).data();
    for (int k = 0; k < 3; ++k) A[k] += d[j] * c[k], Ad[k] += d[p + 1 + j] * c[k];
  }
  out[0] = A[0] / A[2];
  out[1] = A[1] / A[2];
  out[2] = (Ad[0] - Ad[2] * out[0]) / A[2];
  out[3] = (Ad[1] - Ad[2] * out[1]) / A[2];
}

ProductGeometry::ProductGeometry(Kind kind, const BSplineSurface& F, const NurbsCurve2d* meridian,
                                 const NurbsCurve2d& azimuth, bool closed_v, double z0, double z1)
    : kind_(kind), F_(&F), meridian_(meridian), azimuth_(&azimuth), closed_v_(closed_v), z0_(z0),
      z1_(z1), u0_(F.front_u()), u1_(F.back_u()), v0_(F.front_v()), v1_(F.back_v()) {
  if (F.dim() != 1) throw InputError("product geometry: F must be scalar");
  const double tol = 1e-12 * std::max(1.0, std::abs(v1_ - v0_));
  if (std::abs(azimuth.front() - v0_) > tol || std::abs(azimuth.back() - v1_) > tol)
    throw InputError("product geometry: F's v domain does not match the base circle's");
}

ProductGeometry ProductGeometry::polar(const BSplineSurface& F, const BaseCircle& base) {
  return ProductGeometry(Kind::polar, F, nullptr, base.curve(), base.closed(), 0.0, 0.0);
}

ProductGeometry ProductGeometry::spherical(const BSplineSurface& F, const BaseSphere& base) {
  return ProductGeometry(Kind::spherical, F, &base.meridian().curve(), base.azimuth().curve(),
                         base.azimuth().closed(), 0.0, 0.0);
}

ProductGeometry ProductGeometry::cylindrical(const BSplineSurface& F, const BaseCylinder& base) {
  return ProductGeometry(Kind::cylindrical, F, nullptr, base.azimuth().curve(),
                         base.azimuth().closed(), base.z_start(), base.z_end());
}

double ProductGeometry::function(double u, double v) const {
  double f;
  F_->point(u, v, &f);
  return f;
}

// Bae 2002, eqs. (2.1), (3.5) and (3.8) differentiated by the product rule.
void ProductGeometry::evaluate(double u, double v, double* S, double* Su, double* Sv) const {
  double f[3], a[4];
  scalar_and_partials(*F_, u, v, f);
  rational_point_and_derivative(azimuth_->homogeneous(), v, a);
  switch (kind_) {
    case Kind::polar:
      S[0] = f[0] * a[0], S[1] = f[0] * a[1], S[2] = 0.0;
      Su[0] = Su[1] = Su[2] = 0.0;
      Sv[0] = f[2] * a[0] + f[0] * a[2], Sv[1] = f[2] * a[1] + f[0] * a[3], Sv[2] = 0.0;
      return;
    case Kind::spherical: {
      double m[4];  // (z, r, z', r') of the meridian
      rational_point_and_derivative(meridian_->homogeneous(), u, m);
      const double B[3] = {m[1] * a[0], m[1] * a[1], m[0]};
      const double Bu[3] = {m[3] * a[0], m[3] * a[1], m[2]};
      const double Bv[3] = {m[1] * a[2], m[1] * a[3], 0.0};
      for (int k = 0; k < 3; ++k) {
        S[k] = f[0] * B[k];
        Su[k] = f[1] * B[k] + f[0] * Bu[k];
        Sv[k] = f[2] * B[k] + f[0] * Bv[k];
      }
      return;
    }
    case Kind::cylindrical:
      S[0] = f[0] * a[0], S[1] = f[0] * a[1], S[2] = z0_ + u * (z1_ - z0_);
      Su[0] = f[1] * a[0], Su[1] = f[1] * a[1], Su[2] = z1_ - z0_;
      Sv[0] = f[2] * a[0] + f[0] * a[2], Sv[1] = f[2] * a[1] + f[0] * a[3], Sv[2] = 0.0;
      return;
  }
}

Eigen::Vector3d ProductGeometry::point(double u, double v) const {
  Eigen::Vector3d S, Su, Sv;
  evaluate(u, v, S.data(), Su.data(), Sv.data());
  return S;
}

// Gauss–Newton on |S(u, v) − P|² (NURBS Book §6.1 to first order), made robust where the
// Gauss–Newton model is poor (near a pole S_v vanishes while F may still vary in v): a step that
// increases the distance is undone and damped (Levenberg–Marquardt), and a step that reverses the
// previous one in a parameter is shortened to the secant estimate of where the oscillation ends
// (Aitken's Δ²).
FootPoint ProductGeometry::foot_point(const Eigen::Vector3d& P, double u, double v) const {
  FootPoint fp{std::clamp(u, u0_, u1_), std::clamp(v, v0_, v1_), 0.0, false};
  const double period = v1_ - v0_;
  Eigen::Vector3d S, Su, Sv, r, rest;
  double damping = 1e-14, last = std::numeric_limits<double>::infinity();
  double prev_u = fp.u, prev_v = fp.v, du = 0.0, dv = 0.0, last_du = 0.0, last_dv = 0.0;
  for (int it = 0; it < kMaxIterations; ++it) {
    evaluate(fp.u, fp.v, S.data(), Su.data(), Sv.data());
    r = P - S;
    if (r.norm() > last) {  // the step made things worse: back, with more damping
      fp.u = prev_u, fp.v = prev_v;
      damping = std::max(damping * 100.0, 1e-8);
      evaluate(fp.u, fp.v, S.data(), Su.data(), Sv.data());
      r = P - S;
    } else {
      damping = std::max(damping / 10.0, 1e-14);
    }
    last = r.norm();
    const double a = Su.squaredNorm(), b = Su.dot(Sv), c = Sv.squaredNorm();
    const double mu = damping * (a + c) + 1e-300;
    const double gu = Su.dot(r), gv = Sv.dot(r);
    const double det = (a + mu) * (c + mu) - b * b;
    du = ((c + mu) * gu - b * gv) / det, dv = ((a + mu) * gv - b * gu) / det;
    if (du * last_du < 0.0) du *= std::abs(last_du) / (std::abs(last_du) + std::abs(du));
    if (dv * last_dv < 0.0) dv *= std::abs(last_dv) / (std::abs(last_dv) + std::abs(dv));
    last_du = du, last_dv = dv;
    double nu = std::clamp(fp.u + du, u0_, u1_), nv = fp.v + dv;
    if (closed_v_) nv -= period * std::floor((nv - v0_) / period);
    else nv = std::clamp(nv, v0_, v1_);
    du = nu - fp.u;
    dv = closed_v_ ? std::remainder(nv - fp.v, period) : nv - fp.v;
    // The residual after the (projected) step, in the tangent-plane model.
    rest = r - Su * du - Sv * dv;
    const double step = (r - rest).norm();
    prev_u = fp.u, prev_v = fp.v;
    fp.u = nu, fp.v = nv;
    // Converged when the model's distance error, ~κ·step²/2 with κ ~ 1/|S|, is below 1e-10 of it.
    const double size = S.norm();
    if (0.5 * step * step <= 1e-10 * rest.norm() * size || step <= 1e-13 * size) {
      fp.converged = true;
      break;
    }
  }
  // The last step is taken in the tangent-plane model (see the stopping rule).
  const double radial = kind_ == Kind::cylindrical ? r[0] * S[0] + r[1] * S[1] : r.dot(S);
  fp.distance = radial < 0.0 ? -rest.norm() : rest.norm();
  return fp;
}

}  // namespace polarform
