// The surface half of symbolic_product.h: bivariate products of tensor-product B-splines
// (Bae 2002, Appendix B and B.1), the curve procedure applied per direction.
#include <cmath>
#include <numeric>
#include <string>

#include "src/error.h"
#include "src/nurbs/bezier.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_removal.h"
#include "src/nurbs/product_support.h"
#include "src/nurbs/symbolic_product.h"

namespace polarform {

namespace ps = product_support;

// Bae 2002, Appendix B (steps 1-4) with the bivariate Bezier products of eq. (B.6).
BSplineSurface product_rows(const BSplineSurface& unsnapped, const std::vector<int>& factor_rows,
                            const BSplineSurface& g, const std::vector<int>& g_rows,
                            double removal_tol) {
  const BSplineSurface f(unsnapped.degree_u(), unsnapped.degree_v(),
                         snap_knots(unsnapped.knots_u(), g.knots_u()),
                         snap_knots(unsnapped.knots_v(), g.knots_v()), unsnapped.coefs());
  ps::check_row_maps(factor_rows, f.dim(), g_rows, g.dim(), "surface product");
  if (!(removal_tol >= 0.0) || !std::isfinite(removal_tol))
    throw InputError("surface product: removal_tol is " + to_text(removal_tol) +
                     ", expected a finite value >= 0");
  const int pu = f.degree_u(), pv = f.degree_v(), qu = g.degree_u(), qv = g.degree_v();
  const int du = pu + qu, dv = pv + qv;
  const int rows = static_cast<int>(g_rows.size()), fd = f.dim(), gd = g.dim();
  const Knots Ut = product_knots(pu, f.knots_u(), qu, g.knots_u());
  const Knots Vt = product_knots(pv, f.knots_v(), qv, g.knots_v());
  const std::vector<double> ub = ps::break_values(Ut), vb = ps::break_values(Vt);
  const int nsu = static_cast<int>(ub.size()) - 1, nsv = static_cast<int>(vb.size()) - 1;
  const Eigen::MatrixXd F = bezier_stack(f, ub, vb), G = bezier_stack(g, ub, vb);
  const Eigen::MatrixXd wu = ps::bezier_product_weights(pu, qu);
  const Eigen::MatrixXd wv = ps::bezier_product_weights(pv, qv);

  // The full-multiplicity product seen along u: value (r, i, j) at row j·rows + r, column i.
  const int NU = nsu * du + 1, NV = nsv * dv + 1;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows) * NV, NU);
  for (int a = 0; a < nsu; ++a)
    for (int b = 0; b < nsv; ++b)
      for (int iF = 0; iF <= pu; ++iF)
        for (int iG = 0; iG <= qu; ++iG) {
          const int k = iF + iG;
          if (a > 0 && k == 0) continue;  // shared with patch a-1
          for (int jF = 0; jF <= pv; ++jF)
            for (int jG = 0; jG <= qv; ++jG) {
              const int l = jF + jG;
              if (b > 0 && l == 0) continue;  // shared with patch b-1
              const double c = wu(iF, iG) * wv(jF, jG);
              const double* fc = F.col(b * (pv + 1) + jF).data() + (a * (pu + 1) + iF) * fd;
              const double* gc = G.col(b * (qv + 1) + jG).data() + (a * (qu + 1) + iG) * gd;
              double* hc = H.col(a * du + k).data() + (b * dv + l) * rows;
              for (int r = 0; r < rows; ++r) hc[r] += c * fc[factor_rows[r]] * gc[g_rows[r]];
            }
        }
  const Knots Vfull = ps::full_multiplicity_knots(dv, vb);
  const BSpline hu = ps::remove_to_knots(du, ps::full_multiplicity_knots(du, ub), std::move(H), Ut,
                                         rows, "surface product (u)");
  const BSplineSurface su = BSplineSurface::from_along_u(hu, dv, Vfull, rows);
  const BSpline hv =
      ps::remove_to_knots(dv, Vfull, su.along_v().coefs(), Vt, rows, "surface product (v)");
  BSplineSurface h = BSplineSurface::from_along_v(hv, du, Ut, rows);
  if (removal_tol > 0.0)
    h = remove_removable_knots_v(remove_removable_knots_u(h, removal_tol), removal_tol);
  return h;
}

BSplineSurface product(const BSplineSurface& f, const BSplineSurface& g, double removal_tol) {
  std::vector<int> g_rows(g.dim());
  std::iota(g_rows.begin(), g_rows.end(), 0);
  if (f.dim() == 1) return product_rows(f, std::vector<int>(g.dim(), 0), g, g_rows, removal_tol);
  if (f.dim() != g.dim())
    throw InputError("surface product: f has dimension " + std::to_string(f.dim()) +
                     ", expected 1 or " + std::to_string(g.dim()) + " (the dimension of g)");
  return product_rows(f, g_rows, g, g_rows, removal_tol);
}

}  // namespace polarform
