// The curve half of symbolic_product.h: the product knot vector (A.7) and the univariate products
// (Bae 2002, Appendix A.1/A.2).
#include "src/nurbs/symbolic_product.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "src/error.h"
#include "src/nurbs/bezier.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_removal.h"
#include "src/nurbs/product_support.h"

namespace polarform {

namespace ps = product_support;

namespace {

// Interior breakpoints of a validated factor, rejecting discontinuities (multiplicity > degree).
std::vector<Breakpoint> interior_breaks(int degree, const Knots& knots, const char* which) {
  const int n = static_cast<int>(knots.size()) - degree - 1;
  std::vector<Breakpoint> out;
  for (const Breakpoint& b : breakpoints(knots)) {
    if (!(b.value > knots[degree] && b.value < knots[n])) continue;
    if (b.multiplicity > degree)
      throw InputError(std::string("product_knots: ") + which + " has interior knot " +
                       to_text(b.value) + " of multiplicity " + std::to_string(b.multiplicity) +
                       " > its degree " + std::to_string(degree) +
                       " (discontinuous factors are not supported)");
    out.push_back(b);
  }
  return out;
}

void check_removal_tol(double tol, const char* what) {
  if (!(tol >= 0.0) || !std::isfinite(tol))
    throw InputError(std::string(what) + ": removal_tol is " + to_text(tol) +
                     ", expected a finite value >= 0");
}

}  // namespace

Knots snap_knots(const Knots& U, const Knots& V) {
  if (U.empty() || V.empty()) return U;
  const double tol = 1e-12 * std::max(U.back() - U.front(), V.back() - V.front());
  Knots out = U;
  for (double& u : out) {
    const auto it = std::lower_bound(V.begin(), V.end(), u);
    if (it != V.end() && *it != u && *it - u <= tol)
      u = *it;
    else if (it != V.begin() && *(it - 1) != u && u - *(it - 1) <= tol)
      u = *(it - 1);
  }
  return out;
}

// Bae 2002, eq. (A.7); Mørken 1991.
Knots product_knots(int p, const Knots& U, int q, const Knots& V) {
  const int nU = static_cast<int>(U.size()) - p - 1, nV = static_cast<int>(V.size()) - q - 1;
  validate_knots(p, U, nU, "product_knots (first factor)");
  validate_knots(q, V, nV, "product_knots (second factor)");
  const double a = U[p], b = U[nU];
  if (a != V[q] || b != V[nV])
    throw InputError("product_knots: factor domains differ: [" + to_text(a) + ", " + to_text(b) +
                     "] and [" + to_text(V[q]) + ", " + to_text(V[nV]) + "] (start difference " +
                     to_text(V[q] - a) + ", end difference " + to_text(V[nV] - b) + ")");
  const std::vector<Breakpoint> bu = interior_breaks(p, U, "first factor");
  const std::vector<Breakpoint> bv = interior_breaks(q, V, "second factor");
  const int d = p + q;
  Knots out(d + 1, a);
  auto add = [&](double value, int m) { out.insert(out.end(), std::min(m, d), value); };
  std::size_t i = 0, j = 0;
  while (i < bu.size() || j < bv.size()) {
    if (j == bv.size() || (i < bu.size() && bu[i].value < bv[j].value)) {
      add(bu[i].value, bu[i].multiplicity + q);
      ++i;
    } else if (i == bu.size() || bv[j].value < bu[i].value) {
      add(bv[j].value, bv[j].multiplicity + p);
      ++j;
    } else {
      add(bu[i].value, std::max(bu[i].multiplicity + q, bv[j].multiplicity + p));
      ++i, ++j;
    }
  }
  out.insert(out.end(), d + 1, b);
  return out;
}

// Bae 2002, Appendix A.1 (steps 1-4) with the Bezier products of eq. (A.11).
BSpline product_rows(const BSpline& unsnapped, const std::vector<int>& factor_rows,
                     const BSpline& g, const std::vector<int>& g_rows, double removal_tol) {
  const BSpline f(unsnapped.degree(), snap_knots(unsnapped.knots(), g.knots()), unsnapped.coefs());
  ps::check_row_maps(factor_rows, f.dim(), g_rows, g.dim(), "product");
  check_removal_tol(removal_tol, "product");
  const int p = f.degree(), q = g.degree(), d = p + q;
  const int rows = static_cast<int>(g_rows.size());
  const Knots target = product_knots(p, f.knots(), q, g.knots());
  const std::vector<double> breaks = ps::break_values(target);
  const int nseg = static_cast<int>(breaks.size()) - 1;
  const Eigen::MatrixXd F = bezier_stack(f, breaks), G = bezier_stack(g, breaks);
  const Eigen::MatrixXd w = ps::bezier_product_weights(p, q);

  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(rows, nseg * d + 1);
  for (int s = 0; s < nseg; ++s) {
    for (int l = 0; l <= p; ++l) {
      const double* fc = F.col(s * (p + 1) + l).data();
      for (int m = 0; m <= q; ++m) {
        if (s > 0 && l + m == 0) continue;  // the shared first column came from piece s-1
        const double c = w(l, m);
        const double* gc = G.col(s * (q + 1) + m).data();
        double* hc = H.col(s * d + l + m).data();
        for (int r = 0; r < rows; ++r) hc[r] += c * fc[factor_rows[r]] * gc[g_rows[r]];
      }
    }
  }
  BSpline h = ps::remove_to_knots(d, ps::full_multiplicity_knots(d, breaks), std::move(H), target,
                                  rows, "product");
  return removal_tol > 0.0 ? remove_removable_knots(h, removal_tol) : h;
}

BSpline product(const BSpline& f, const BSpline& g, double removal_tol) {
  std::vector<int> g_rows(g.dim());
  std::iota(g_rows.begin(), g_rows.end(), 0);
  if (f.dim() == 1) return product_rows(f, std::vector<int>(g.dim(), 0), g, g_rows, removal_tol);
  if (f.dim() != g.dim())
    throw InputError("product: f has dimension " + std::to_string(f.dim()) + ", expected 1 or " +
                     std::to_string(g.dim()) + " (the dimension of g)");
  return product_rows(f, g_rows, g, g_rows, removal_tol);
}

}  // namespace polarform
