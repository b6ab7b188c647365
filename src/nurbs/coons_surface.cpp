// Bilinearly and bicubically blended Coons patches built on control points (Piegl & Tiller 2001,
// §2.1–2.2; spec P1–P2): S = L_u + L_v − T, the three made compatible by common_basis.
#include "src/nurbs/coons_surface.h"

#include <array>
#include <string>
#include <utility>

#include "src/error.h"
#include "src/nurbs/common_basis.h"
#include "src/nurbs/ruled_surface.h"

namespace polarform {

namespace {

void check_non_rational(const NurbsCurve3d& c, const char* what) {
  if (c.is_rational())
    throw InputError(std::string("Coons patch: ") + what +
                     " is rational; expected a non-rational B-spline (a homogeneous Coons patch "
                     "is not supported)");
}

// The same surface with u and v exchanged.
BSplineSurface transposed(const BSplineSurface& s) {
  Eigen::MatrixXd P(s.dim(), s.coefs().cols());
  for (int i = 0; i < s.size_u(); ++i)
    for (int j = 0; j < s.size_v(); ++j) P.col(j * s.size_u() + i) = s.coef(i, j);
  return BSplineSurface(s.degree_v(), s.degree_u(), s.knots_v(), s.knots_u(), std::move(P));
}

// P = P_Lu + P_Lv − P_T on one basis (non-rational parts, weight rows all 1).
NurbsSurface boolean_sum(const BSplineSurface& lu, const BSplineSurface& lv,
                         const BSplineSurface& t) {
  const BSplineSurface all = common_basis(std::vector<BSplineSurface>{lu, lv, t});
  Eigen::MatrixXd P(4, all.coefs().cols());
  P.topRows<3>() =
      all.coefs().middleRows<3>(0) + all.coefs().middleRows<3>(4) - all.coefs().middleRows<3>(8);
  P.row(3).setOnes();
  return NurbsSurface(
      BSplineSurface(all.degree_u(), all.degree_v(), all.knots_u(), all.knots_v(), std::move(P)));
}

// H1(v)·a(u) + H2(v)·b(u) + H3(v)·da(u) + H4(v)·db(u) as a surface cubic in v: the cubic Hermite
// blends in Bezier form, rows a, a + da/3, b − db/3, b (P&T 2001, §2.2).
BSplineSurface hermite_loft(const NurbsCurve3d& a, const NurbsCurve3d& b, const NurbsCurve3d& da,
                            const NurbsCurve3d& db) {
  const BSpline c =
      common_basis({a.homogeneous(), b.homogeneous(), da.homogeneous(), db.homogeneous()});
  const auto& Q = c.coefs();
  Eigen::MatrixXd P(4, 4 * c.size());
  for (int i = 0; i < c.size(); ++i) {
    const Eigen::Vector3d A = Q.col(i).segment<3>(0), B = Q.col(i).segment<3>(4);
    const Eigen::Vector3d dA = Q.col(i).segment<3>(8), dB = Q.col(i).segment<3>(12);
    P.col(4 * i) << A, 1.0;
    P.col(4 * i + 1) << A + dA / 3.0, 1.0;
    P.col(4 * i + 2) << B - dB / 3.0, 1.0;
    P.col(4 * i + 3) << B, 1.0;
  }
  return BSplineSurface(c.degree(), 3, c.knots(), {0, 0, 0, 0, 1, 1, 1, 1}, std::move(P));
}

Eigen::Vector3d tangent(const NurbsCurve3d& c, double t) { return c.derivatives(t, 1)[1]; }

}  // namespace

// Piegl & Tiller 2001, §2.1: bilinearly blended Coons patch as a Boolean sum of control nets.
NurbsSurface bilinear_coons(const PatchBoundary& b) {
  check_non_rational(b.u0, "boundary u0");
  check_non_rational(b.u1, "boundary u1");
  check_non_rational(b.v0, "boundary v0");
  check_non_rational(b.v1, "boundary v1");
  const BSplineSurface lu = ruled_surface(b.u0, b.u1).homogeneous();
  const BSplineSurface lv = transposed(ruled_surface(b.v0, b.v1).homogeneous());
  const BSplineSurface t =
      bilinear_surface(b.u0.point(0), b.u0.point(1), b.u1.point(0), b.u1.point(1)).homogeneous();
  return boolean_sum(lu, lv, t);
}

// Piegl & Tiller 2001, §2.2: bicubically blended Coons patch; T is the bicubic Hermite interpolant
// of (S, S_u, S_v, S_uv) at the corners in Bezier form, b_01 = S + S_v/3, b_11 = S + S_u/3 + S_v/3
// + S_uv/9 (and mirrored at the other corners).
NurbsSurface bicubic_coons(const PatchBoundary& b, const CrossDerivatives& d) {
  using Named = std::pair<const NurbsCurve3d*, const char*>;
  for (const auto& [c, what] :
       std::array<Named, 8>{Named{&b.u0, "boundary u0"}, Named{&b.u1, "boundary u1"},
                            Named{&b.v0, "boundary v0"}, Named{&b.v1, "boundary v1"},
                            Named{&d.du0, "derivative du0"}, Named{&d.du1, "derivative du1"},
                            Named{&d.dv0, "derivative dv0"}, Named{&d.dv1, "derivative dv1"}})
    check_non_rational(*c, what);
  const BSplineSurface lu = hermite_loft(b.u0, b.u1, d.dv0, d.dv1);
  const BSplineSurface lv = transposed(hermite_loft(b.v0, b.v1, d.du0, d.du1));
  Eigen::MatrixXd P(4, 16);
  for (int a = 0; a <= 1; ++a)
    for (int c = 0; c <= 1; ++c) {
      const NurbsCurve3d& along_u = c == 0 ? b.u0 : b.u1;  // S(·, c)
      const NurbsCurve3d& along_v = a == 0 ? b.v0 : b.v1;  // S(a, ·)
      const NurbsCurve3d& dv = c == 0 ? d.dv0 : d.dv1;     // S_v(·, c)
      const NurbsCurve3d& du = a == 0 ? d.du0 : d.du1;     // S_u(a, ·)
      const Eigen::Vector3d S = along_u.point(a), Su = tangent(along_u, a),
                            Sv = tangent(along_v, c);
      const Eigen::Vector3d Suv = 0.5 * (tangent(dv, a) + tangent(du, c));
      const double su = a == 0 ? 1.0 : -1.0, sv = c == 0 ? 1.0 : -1.0;
      const int i0 = 3 * a, i1 = a == 0 ? 1 : 2, j0 = 3 * c, j1 = c == 0 ? 1 : 2;
      P.col(4 * i0 + j0) << S, 1.0;
      P.col(4 * i1 + j0) << S + su * Su / 3.0, 1.0;
      P.col(4 * i0 + j1) << S + sv * Sv / 3.0, 1.0;
      P.col(4 * i1 + j1) << S + su * Su / 3.0 + sv * Sv / 3.0 + su * sv * Suv / 9.0, 1.0;
    }
  const Knots bezier{0, 0, 0, 0, 1, 1, 1, 1};
  return boolean_sum(lu, lv, BSplineSurface(3, 3, bezier, bezier, std::move(P)));
}

}  // namespace polarform
