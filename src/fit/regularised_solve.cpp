#include "src/fit/regularised_solve.h"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "src/error.h"

namespace polarform {

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Ldlt = Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>;

// Smallest pivot of LDL^T relative to the largest that still counts as non-singular.
constexpr double kPivotRatio = 1e-13;

class Factorised {
 public:
  Factorised(const NormalEquations& ne, const Sparse& T)
      : ne_(ne), T_(T), As_(ne.A / ne.weight_sum), bs_(ne.b / ne.weight_sum) {
    ldlt_.analyzePattern(Sparse(As_ + T_));
  }

  // Factorises A/W + λT; false when singular to working precision (ratio() says how).
  bool factorise(double lambda) {
    ldlt_.factorize(Sparse(As_ + lambda * T_));
    if (ldlt_.info() != Eigen::Success) {
      ratio_ = 0.0;
      return false;
    }
    const Eigen::VectorXd D = ldlt_.vectorD();
    const double dmax = D.cwiseAbs().maxCoeff();
    ratio_ = dmax > 0.0 ? D.minCoeff() / dmax : 0.0;
    return ratio_ > kPivotRatio;
  }
  double ratio() const { return ratio_; }

  Eigen::VectorXd solve() const { return ldlt_.solve(bs_); }
  double rss(const Eigen::VectorXd& x) const {
    return std::max(0.0, ne_.gg - 2.0 * x.dot(ne_.b) + x.dot(ne_.A * x));
  }
  // Hutchinson's estimate of tr(M^{-1} A/W) with fixed Rademacher probes.
  double dof(int probes) const {
    std::mt19937_64 rng(20020101);
    std::bernoulli_distribution coin(0.5);
    double sum = 0.0;
    for (int p = 0; p < probes; ++p) {
      Eigen::VectorXd z(As_.rows());
      for (Eigen::Index i = 0; i < z.size(); ++i) z[i] = coin(rng) ? 1.0 : -1.0;
      sum += z.dot(ldlt_.solve(As_ * z));
    }
    return sum / probes;
  }

 private:
  const NormalEquations& ne_;
  const Sparse& T_;
  Sparse As_;
  Eigen::VectorXd bs_;
  Ldlt ldlt_;
  double ratio_ = 0.0;
};

[[noreturn]] void singular(double lambda, double ratio, Eigen::Index unknowns) {
  std::ostringstream msg;
  msg << "least-squares fit: the normal equations (" << unknowns << " unknowns, fairness weight "
      << lambda << ") are singular to working precision (smallest/largest pivot " << ratio
      << ", need > " << kPivotRatio << "); some control values have no data: use a fairness weight"
      << " > 0 or fewer control points";
  throw NumericalError(msg.str());
}

// Reference λ: the data term's trace over the energy's (0 when the energy vanishes identically).
double lambda_scale(const NormalEquations& ne, const Sparse& T) {
  const double tt = T.diagonal().sum();
  return tt > 0.0 ? (ne.A.diagonal().sum() / ne.weight_sum) / tt : 0.0;
}

// Generalized cross-validation over log10 λ: a decade grid around the reference, λ = 0 as a
// candidate, then golden-section refinement of the best bracket.
RegularisedSolution gcv_solve(Factorised& f, const NormalEquations& ne, double ref, int probes) {
  const double n = static_cast<double>(ne.count);
  const double inf = std::numeric_limits<double>::infinity();
  auto gcv = [&](double lambda, RegularisedSolution* keep) {
    if (!f.factorise(lambda)) return inf;
    const Eigen::VectorXd x = f.solve();
    const double rss = f.rss(x), dof = f.dof(probes);
    const double denom = 1.0 - dof / n;
    const double g = denom > 0.0 ? (rss / ne.weight_sum) / (denom * denom) : inf;
    if (keep) *keep = RegularisedSolution{x, lambda, rss, dof, g};
    return g;
  };
  RegularisedSolution best;
  double best_g = gcv(0.0, &best);
  if (ref <= 0.0) {
    if (best_g == inf) singular(0.0, f.ratio(), ne.b.size());
    return best;
  }
  int best_e = 99;  // decade of the best grid λ (99: λ = 0)
  for (int e = -10; e <= 4; ++e) {
    RegularisedSolution s;
    const double g = gcv(ref * std::pow(10.0, e), &s);
    if (g < best_g) best_g = g, best = s, best_e = e;
  }
  if (best_g == inf) singular(ref * 1e4, f.ratio(), ne.b.size());
  if (best_e == 99) return best;
  const double phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = best_e - 1.0, b = best_e + 1.0;
  double c = b - phi * (b - a), d = a + phi * (b - a);
  double gc = gcv(ref * std::pow(10.0, c), nullptr), gd = gcv(ref * std::pow(10.0, d), nullptr);
  for (int it = 0; it < 12; ++it) {
    if (gc < gd) b = d, d = c, gd = gc, c = b - phi * (b - a), gc = gcv(ref * std::pow(10.0, c), nullptr);
    else a = c, c = d, gc = gd, d = a + phi * (b - a), gd = gcv(ref * std::pow(10.0, d), nullptr);
  }
  RegularisedSolution s;
  const double g = gcv(ref * std::pow(10.0, 0.5 * (a + b)), &s);
  return g < best_g ? s : best;
}

}  // namespace

RegularisedSolution solve_regularised(const NormalEquations& ne, const Sparse& T,
                                      const FairnessOptions& options) {
  if (T.rows() != ne.A.rows() || T.cols() != ne.A.cols())
    throw InputError("regularised solve: energy matrix " + std::to_string(T.rows()) + " x " +
                     std::to_string(T.cols()) + " for " + std::to_string(ne.A.rows()) + " unknowns");
  if (!(options.weight >= 0.0) || !std::isfinite(options.weight))
    throw InputError("fairness weight " + std::to_string(options.weight) +
                     ": expected a finite value >= 0");
  if (options.mode == FairnessOptions::Mode::gcv && options.gcv_probes < 1)
    throw InputError("fairness gcv_probes " + std::to_string(options.gcv_probes) + ": expected >= 1");
  Factorised f(ne, T);
  const double ref = lambda_scale(ne, T);
  if (options.mode == FairnessOptions::Mode::gcv) return gcv_solve(f, ne, ref, options.gcv_probes);
  const double lambda =
      options.mode == FairnessOptions::Mode::fixed ? options.weight : options.weight * ref;
  if (!f.factorise(lambda)) singular(lambda, f.ratio(), ne.b.size());
  RegularisedSolution s;
  s.x = f.solve();
  s.lambda = lambda;
  s.rss = f.rss(s.x);
  return s;
}

}  // namespace polarform
