#include "src/nurbs/surface_jet.h"

#include "src/nurbs/basis.h"

namespace polarform {

SurfaceJet surface_jet(const NurbsSurface& surface, double u, double v) {
  const BSplineSurface& h = surface.homogeneous();
  const int pu = h.degree_u(), pv = h.degree_v(), nu = h.size_u(), nv = h.size_v();
  const int su = find_span(pu, h.knots_u(), nu, u), sv = find_span(pv, h.knots_v(), nv, v);
  // Basis derivatives 0..2: Du[k * (pu + 1) + a]; NURBS Book A2.3.
  double Du[3 * (kMaxDegree + 1)], Dv[3 * (kMaxDegree + 1)];
  ders_basis_funs(su, u, pu, 2, h.knots_u(), Du);
  ders_basis_funs(sv, v, pv, 2, h.knots_v(), Dv);
  // Homogeneous partials A_{kl} (w·S and w); NURBS Book A3.6.
  Eigen::Vector4d A00 = Eigen::Vector4d::Zero(), A10 = A00, A01 = A00, A20 = A00, A11 = A00, A02 = A00;
  const double* coefs = h.coefs().data();
  for (int a = 0; a <= pu; ++a) {
    Eigen::Vector4d row0 = Eigen::Vector4d::Zero(), row1 = row0, row2 = row0;
    for (int b = 0; b <= pv; ++b) {
      const Eigen::Map<const Eigen::Vector4d> c(coefs + 4 * ((su - pu + a) * nv + sv - pv + b));
      row0 += Dv[b] * c;
      row1 += Dv[(pv + 1) + b] * c;
      row2 += Dv[2 * (pv + 1) + b] * c;
    }
    const double n0 = Du[a], n1 = Du[(pu + 1) + a], n2 = Du[2 * (pu + 1) + a];
    A00 += n0 * row0, A01 += n0 * row1, A02 += n0 * row2;
    A10 += n1 * row0, A11 += n1 * row1, A20 += n2 * row0;
  }
  // Rational quotient rule; NURBS Book A4.4 for d = 2.
  const double w = A00[3];
  SurfaceJet j;
  j.s = A00.head<3>() / w;
  j.su = (A10.head<3>() - A10[3] * j.s) / w;
  j.sv = (A01.head<3>() - A01[3] * j.s) / w;
  j.suu = (A20.head<3>() - 2.0 * A10[3] * j.su - A20[3] * j.s) / w;
  j.svv = (A02.head<3>() - 2.0 * A01[3] * j.sv - A02[3] * j.s) / w;
  j.suv = (A11.head<3>() - A10[3] * j.sv - A01[3] * j.su - A11[3] * j.s) / w;
  return j;
}

}  // namespace polarform
