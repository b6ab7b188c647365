#include "designers/convert/function_spline.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "designers/convert/knot_placement.h"
#include "designers/convert/refined_maximum.h"
#include "src/error.h"
#include "src/fit/constrained_least_squares.h"
#include "src/number_text.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/knot_removal.h"

namespace polarform {

namespace {

constexpr int kDegree = 5;

// R, R', R'' at t as one-sided limits from inside a smooth piece: evaluated at t + h (h tiny, of
// the side's sign) and carried to t by Taylor expansion, so a jump at t cannot leak in.
Eigen::Vector3d one_sided_jet(const PolarFunction& R, double t, double h) {
  double d[4];
  R.derivatives(t + h, 3, d);
  const double s = -h;
  return {d[0] + s * d[1] + s * s / 2 * d[2] + s * s * s / 6 * d[3],
          d[1] + s * d[2] + s * s / 2 * d[3], d[2] + s * d[3]};
}

// The quintic with simple knots at `breaks` meeting the one-sided jets of R at both ends exactly
// and fitting R at interior samples by least squares (Bae 2002, Appendix C).
BSpline fit_segment(const PolarFunction& R, const std::vector<double>& breaks) {
  const double a = breaks.front(), b = breaks.back();
  const int spans = static_cast<int>(breaks.size()) - 1;
  const Knots U = clamped_knots(kDegree, a, b, std::vector<double>(breaks.begin() + 1, breaks.end() - 1));
  const int n = spans + kDegree;
  constexpr int kPerSpan = 4;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(spans * kPerSpan, n), B(spans * kPerSpan, 1);
  double N[kMaxDegree + 1];
  for (int s = 0; s < spans; ++s)
    for (int k = 0; k < kPerSpan; ++k) {
      const int row = s * kPerSpan + k;
      const double t = breaks[s] + (breaks[s + 1] - breaks[s]) * (k + 0.5) / kPerSpan;
      basis_funs(s + kDegree, t, kDegree, U, N);
      for (int j = 0; j <= kDegree; ++j) A(row, s + j) = N[j];
      B(row, 0) = R(t);
    }
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(6, n), D(6, 1);
  const double delta = 1e-9 * (b - a);
  const Eigen::MatrixXd Da = ders_basis_funs(kDegree, a, kDegree, 2, U);
  const Eigen::MatrixXd Db = ders_basis_funs(n - 1, b, kDegree, 2, U);
  C.block(0, 0, 3, kDegree + 1) = Da;
  C.block(3, n - kDegree - 1, 3, kDegree + 1) = Db;
  D.block(0, 0, 3, 1) = one_sided_jet(R, a, delta);
  D.block(3, 0, 3, 1) = one_sided_jet(R, b, -delta);
  return BSpline(kDegree, U, constrained_least_squares(A, B, C, D).transpose());
}

// Joins per-segment quintics (clamped, meeting at their ends) into one spline, then removes at
// each join the knots the actual continuity there allows (at round-off).
BSpline join_segments(const std::vector<BSpline>& pieces) {
  Knots U(kDegree + 1, pieces.front().front());
  std::vector<double> joins;
  int n = 0;
  for (const BSpline& p : pieces) n += p.size() - (n ? 1 : 0);
  Eigen::MatrixXd coefs(1, n);
  int at = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const BSpline& p = pieces[k];
    const Knots& pk = p.knots();
    if (k > 0) {
      // Both pieces meet R's value at the join: share that control value.
      coefs(0, at - 1) = 0.5 * (coefs(0, at - 1) + p.coefs()(0, 0));
      joins.push_back(p.front());
      U.insert(U.end(), kDegree, p.front());
    }
    U.insert(U.end(), pk.begin() + kDegree + 1, pk.end() - kDegree - 1);
    const int skip = k > 0 ? 1 : 0;
    coefs.middleCols(at, p.size() - skip) = p.coefs().rightCols(p.size() - skip);
    at += p.size() - skip;
  }
  U.insert(U.end(), kDegree + 1, pieces.back().back());
  BSpline f(kDegree, std::move(U), std::move(coefs));
  const double round_off = 1e-12 * std::max(1.0, f.coefs().cwiseAbs().maxCoeff());
  for (double t : joins) f = remove_knot(f, t, kDegree - 1, round_off).spline;
  return f;
}

// The largest sampled |F − R| in each span between consecutive breaks.
std::vector<double> span_errors(const BSplineFunction& F, const PolarFunction& R,
                                const std::vector<double>& breaks) {
  constexpr int kSamples = 6;
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    double worst = 0.0;
    for (int k = 0; k <= kSamples; ++k) {
      const double t = breaks[i] + (breaks[i + 1] - breaks[i]) * k / kSamples;
      worst = std::max(worst, std::abs(F(t) - R(t)));
    }
    out.push_back(worst);
  }
  return out;
}

// New breaks on [breaks.front(), breaks.back()] that equidistribute the predicted error: a span
// with error e needs (e/goal)^(1/6) spans of its kind (quintic: error ∝ h^6); de Boor's NEWNOT
// (knot_placement.h) over that mass, at least `at_least` spans.
std::vector<double> equidistributed_breaks(const std::vector<double>& breaks,
                                           const std::vector<double>& errors, double goal,
                                           int at_least) {
  std::vector<double> mass;
  for (double e : errors) mass.push_back(std::pow(std::max(e, 1e-6 * goal) / goal, 1.0 / 6));
  const double needed = std::accumulate(mass.begin(), mass.end(), 0.0);
  const int spans = std::max(at_least, static_cast<int>(std::ceil(needed)));
  return equidistribute(breaks, mass, spans, {breaks.front(), breaks.back()});
}

bool is_constant(const PolarFunction& R, const std::vector<double>& grid) {
  const double r0 = R(grid.front());
  for (std::size_t s = 0; s + 1 < grid.size(); ++s)
    for (int k = 0; k <= 8; ++k) {
      double d[2];
      R.derivatives(grid[s] + (grid[s + 1] - grid[s]) * k / 8, 1, d);
      if (d[0] != r0 || d[1] != 0.0) return false;
    }
  return true;
}

}  // namespace

double max_function_error(const BSplineFunction& F, const PolarFunction& R, int per_span) {
  auto error = [&](double t) { return std::abs(F(t) - R(t)); };
  std::vector<double> grid;
  for (const Breakpoint& b : breakpoints(F.knots()))
    if (b.value >= F.front() && b.value <= F.back()) grid.push_back(b.value);
  return refined_maximum(error, grid, per_span, 3).value;
}

FunctionSpline represent_as_bspline(const PolarFunction& R, double tol) {
  if (!(R.end > R.start)) throw InputError("polar function: empty angular domain");
  if (!(tol > 0)) throw InputError("conversion tolerance must be > 0");
  std::vector<double> grid{R.start};
  for (double b : R.breakpoints) grid.push_back(b);
  grid.push_back(R.end);

  if (R.exact) {
    // Keep only the knots the function's continuity needs (at round-off).
    const BSpline& e = R.exact->spline();
    const double round_off = 1e-12 * std::max(1.0, e.coefs().cwiseAbs().maxCoeff());
    return {BSplineFunction(remove_removable_knots(e, round_off)), 0.0, true};
  }
  if (is_constant(R, grid)) {
    const BSplineFunction constant(0, {R.start, R.end}, Eigen::VectorXd::Constant(1, R(R.start)));
    return {constant, 0.0, true};
  }

  // Per smooth segment: one span settles polynomial and constant pieces; otherwise refit with
  // breaks that equidistribute the measured error until it meets the budget.
  const double target = 0.9 * tol;
  std::vector<BSpline> pieces;
  double worst = 0.0;
  for (std::size_t s = 0; s + 1 < grid.size(); ++s) {
    std::vector<double> breaks{grid[s], grid[s + 1]};
    for (int round = 0;; ++round) {
      BSpline piece = fit_segment(R, breaks);
      const BSplineFunction F(piece);
      const std::vector<double> errors = span_errors(F, R, breaks);
      const double sampled = *std::max_element(errors.begin(), errors.end());
      const double e = sampled <= target ? max_function_error(F, R) : sampled;
      if (e <= target) {
        worst = std::max(worst, e);
        pieces.push_back(std::move(piece));
        break;
      }
      const int spans = static_cast<int>(breaks.size()) - 1;
      if (round == 12 || spans > 5000)
        throw NumericalError("representing R(θ) as a B-spline: error " + number_text(e) +
                             " mm with " + std::to_string(spans) + " spans between " +
                             degrees_text(grid[s]) + " and " + degrees_text(grid[s + 1]) +
                             " still exceeds " + number_text(target) + " mm");
      breaks = spans == 1 ? std::vector<double>{grid[s], grid[s] + (grid[s + 1] - grid[s]) / 4,
                                               grid[s] + (grid[s + 1] - grid[s]) / 2,
                                               grid[s] + 3 * (grid[s + 1] - grid[s]) / 4, grid[s + 1]}
                          : equidistributed_breaks(breaks, errors, 0.7 * target, spans + 1);
    }
  }
  // Joining moves F by round-off only; the pieces' measured errors stand for the whole.
  return {BSplineFunction(join_segments(pieces)), worst, false};
}

}  // namespace polarform
