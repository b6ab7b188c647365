#include "src/nurbs/product_support.h"

#include <string>

#include "src/error.h"
#include "src/nurbs/binomial.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_remover.h"

namespace polarform::product_support {

namespace {

// Relative size of the coefficient mismatch that still counts as round-off in an exact removal.
constexpr double kExactRemovalTolerance = 1e-9;

}  // namespace

// Bae 2002, eq. (A.11).
Eigen::MatrixXd bezier_product_weights(int p, int q) {
  Eigen::MatrixXd w(p + 1, q + 1);
  for (int l = 0; l <= p; ++l)
    for (int m = 0; m <= q; ++m) w(l, m) = binomial(p, l) * binomial(q, m) / binomial(p + q, l + m);
  return w;
}

std::vector<double> break_values(const Knots& knots) {
  std::vector<double> out;
  for (double k : knots)
    if (out.empty() || out.back() != k) out.push_back(k);
  return out;
}

// Bae 2002, eq. (A.8).
Knots full_multiplicity_knots(int d, const std::vector<double>& breaks) {
  Knots U(d + 1, breaks.front());
  for (std::size_t i = 1; i + 1 < breaks.size(); ++i) U.insert(U.end(), d, breaks[i]);
  U.insert(U.end(), d + 1, breaks.back());
  return U;
}

void check_row_maps(const std::vector<int>& factor_rows, int factor_dim,
                    const std::vector<int>& g_rows, int g_dim, const char* what) {
  if (factor_rows.empty() || factor_rows.size() != g_rows.size())
    throw InputError(std::string(what) + ": factor_rows has " + std::to_string(factor_rows.size()) +
                     " entries and g_rows " + std::to_string(g_rows.size()) +
                     ", expected the same positive number");
  for (std::size_t r = 0; r < g_rows.size(); ++r) {
    if (factor_rows[r] < 0 || factor_rows[r] >= factor_dim)
      throw InputError(std::string(what) + ": factor_rows[" + std::to_string(r) +
                       "] = " + std::to_string(factor_rows[r]) + ", expected 0.." +
                       std::to_string(factor_dim - 1));
    if (g_rows[r] < 0 || g_rows[r] >= g_dim)
      throw InputError(std::string(what) + ": g_rows[" + std::to_string(r) + "] = " +
                       std::to_string(g_rows[r]) + ", expected 0.." + std::to_string(g_dim - 1));
  }
}

// Bae 2002, Appendix A.1 step 4: remove the knots of U_H^C = Û_H - U_H (NURBS Book A5.8).
BSpline remove_to_knots(int d, Knots full_knots, Eigen::MatrixXd coefs, const Knots& target,
                        int point_dim, const char* what) {
  const double tol = kExactRemovalTolerance * coefs.cwiseAbs().maxCoeff();
  KnotRemover remover(d, std::move(full_knots), std::move(coefs), point_dim);
  for (const Breakpoint& b : breakpoints(target)) {
    if (b.value == target.front() || b.value == target.back()) continue;
    const int excess = d - b.multiplicity;
    if (excess <= 0) continue;
    const KnotRemover::Outcome out = remover.remove(b.value, excess, tol);
    if (out.removed < excess)
      throw NumericalError(std::string(what) + ": knot " + to_text(b.value) + " should drop " +
                           std::to_string(excess) + " times to multiplicity " +
                           std::to_string(b.multiplicity) + " (A.7) but only " +
                           std::to_string(out.removed) + " went: deviation " +
                           to_text(out.refused_deviation) + " > round-off bound " + to_text(tol));
  }
  return std::move(remover).finish();
}

}  // namespace polarform::product_support
