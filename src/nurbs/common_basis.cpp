#include "src/nurbs/common_basis.h"

#include <algorithm>
#include <string>

#include "src/error.h"
#include "src/nurbs/degree_elevation.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_refinement.h"
#include "src/nurbs/knot_search.h"
#include "src/nurbs/periodic.h"

namespace polarform {

namespace {

void check_domain(double front, double back, double f0, double b0, std::size_t i, const char* dir) {
  if (front != f0 || back != b0)
    throw InputError(std::string("common_basis: part ") + std::to_string(i) + " has " + dir +
                     "domain [" + to_text(front) + ", " + to_text(back) + "], expected [" +
                     to_text(f0) + ", " + to_text(b0) + "]");
}

// Union of knot vectors, each value with its highest multiplicity.
Knots merge_knots(const std::vector<const Knots*>& all) {
  std::vector<Breakpoint> merged;
  for (const Knots* k : all) {
    for (const Breakpoint& b : breakpoints(*k)) {
      auto it = std::lower_bound(merged.begin(), merged.end(), b.value,
                                 [](const Breakpoint& x, double v) { return x.value < v; });
      if (it != merged.end() && it->value == b.value)
        it->multiplicity = std::max(it->multiplicity, b.multiplicity);
      else
        merged.insert(it, b);
    }
  }
  Knots out;
  for (const Breakpoint& b : merged) out.insert(out.end(), b.multiplicity, b.value);
  return out;
}

// The knots of `target` that `own` lacks (multiset difference; own ⊂ target).
std::vector<double> missing_knots(const Knots& target, const Knots& own) {
  std::vector<double> X;
  for (const Breakpoint& b : breakpoints(target))
    X.insert(X.end(), std::max(0, b.multiplicity - sorted_multiplicity(own, b.value)), b.value);
  return X;
}

}  // namespace

// NURBS Book A5.9 to the highest degree, then A5.4 to the merged knots.
BSpline common_basis(const std::vector<BSpline>& parts) {
  if (parts.empty()) throw InputError("common_basis: no parts");
  int degree = 0, dim = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    check_domain(parts[i].front(), parts[i].back(), parts[0].front(), parts[0].back(), i, "");
    degree = std::max(degree, parts[i].degree());
    dim += parts[i].dim();
  }
  std::vector<BSpline> raised;
  std::vector<const Knots*> knots;
  for (const BSpline& c : parts)  // clamped first, so that all knot vectors end alike
    raised.push_back(elevate_degree(clip(c, c.front(), c.back()), degree - c.degree()));
  for (const BSpline& c : raised) knots.push_back(&c.knots());
  const Knots U = merge_knots(knots);
  Eigen::MatrixXd P(dim, static_cast<Eigen::Index>(U.size()) - degree - 1);
  int row = 0;
  for (const BSpline& c : raised) {
    const BSpline r = refine_knots(c, missing_knots(U, c.knots()));
    P.middleRows(row, r.dim()) = r.coefs();
    row += r.dim();
  }
  return BSpline(degree, U, std::move(P));
}

BSplineSurface common_basis(const std::vector<BSplineSurface>& parts) {
  if (parts.empty()) throw InputError("common_basis: no parts");
  int pu = 0, pv = 0, dim = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const BSplineSurface& s = parts[i];
    check_domain(s.front_u(), s.back_u(), parts[0].front_u(), parts[0].back_u(), i, "u-");
    check_domain(s.front_v(), s.back_v(), parts[0].front_v(), parts[0].back_v(), i, "v-");
    pu = std::max(pu, s.degree_u());
    pv = std::max(pv, s.degree_v());
    dim += s.dim();
  }
  std::vector<BSplineSurface> raised;
  std::vector<const Knots*> ku, kv;
  for (const BSplineSurface& s : parts) {
    const BSplineSurface c = clip_v(clip_u(s, s.front_u(), s.back_u()), s.front_v(), s.back_v());
    raised.push_back(elevate_degree_v(elevate_degree_u(c, pu - s.degree_u()), pv - s.degree_v()));
  }
  for (const BSplineSurface& s : raised) {
    ku.push_back(&s.knots_u());
    kv.push_back(&s.knots_v());
  }
  const Knots U = merge_knots(ku), V = merge_knots(kv);
  const Eigen::Index nu = static_cast<Eigen::Index>(U.size()) - pu - 1;
  const Eigen::Index nv = static_cast<Eigen::Index>(V.size()) - pv - 1;
  Eigen::MatrixXd P(dim, nu * nv);
  int row = 0;
  for (const BSplineSurface& s : raised) {
    const BSplineSurface r = refine_knots_v(refine_knots_u(s, missing_knots(U, s.knots_u())),
                                            missing_knots(V, s.knots_v()));
    P.middleRows(row, r.dim()) = r.coefs();
    row += r.dim();
  }
  return BSplineSurface(pu, pv, U, V, std::move(P));
}

}  // namespace polarform
