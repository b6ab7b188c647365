#include "designers/vessel/synthesis_space.h"

#include <Eigen/QR>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "src/error.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/error_text.h"

namespace polarform {

namespace {

const char* unit_of(int order) {
  static const char* units[] = {"mm", "mm/rad", "mm/rad²"};
  return units[order];
}

std::string value_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", x);
  return buf;
}

std::string space_text(const SynthesisSpace& space) {
  return "degree " + std::to_string(space.degree) + ", " + std::to_string(space.ordinates()) +
         " ordinates" + (space.unknowns() < space.ordinates() ? ", symmetric about θ = 90°" : "");
}

}  // namespace

SynthesisSpace synthesis_space(const SynthesisSettings& s) {
  if (s.degree < 3 || s.degree > kMaxDegree)
    throw InputError("synthesis: degree " + std::to_string(s.degree) + " outside [3, " +
                     std::to_string(kMaxDegree) + "] (∫(R''')² dθ needs degree >= 3)");
  if (s.ordinates < s.degree + 1 || s.ordinates > kMaxOrdinates)
    throw InputError("synthesis: ordinates " + std::to_string(s.ordinates) +
                     ", expected in [degree + 1 = " + std::to_string(s.degree + 1) + ", " +
                     std::to_string(kMaxOrdinates) + "]");
  if (!(s.smoothing >= 0.0 && std::isfinite(s.smoothing)))
    throw InputError("synthesis: smoothing " + to_text(s.smoothing) + ", expected a finite λ >= 0");
  if (s.max_iterations < 1 || s.max_iterations > kMaxSynthesisIterations)
    throw InputError("synthesis: max-iterations " + std::to_string(s.max_iterations) +
                     ", expected in [1, " + std::to_string(kMaxSynthesisIterations) + "]");

  SynthesisSpace space;
  space.degree = s.degree;
  space.knots = uniform_clamped_knots(s.degree, s.ordinates - s.degree, 0.0, std::numbers::pi);
  const int n = s.ordinates, m = s.symmetric ? (n + 1) / 2 : n;
  space.map = Eigen::MatrixXd::Zero(n, m);
  for (int i = 0; i < n; ++i) space.map(i, s.symmetric ? std::min(i, n - 1 - i) : i) = 1.0;
  return space;
}

std::string EndConstraint::name() const {
  return "R" + std::string(order, '\'') + (end == 'A' ? "(0)" : end == 'B' ? "(π)" : "(π/2)");
}

double EndConstraint::theta() const {
  return end == 'A' ? 0.0 : end == 'B' ? std::numbers::pi : std::numbers::pi / 2;
}

EndConstraints end_constraints(const SynthesisSpace& space, const EndCondition& end_a,
                               const EndCondition& end_b, double length_unit,
                               std::optional<double> depth) {
  const int p = space.degree, n = space.ordinates();
  EndConstraints out;
  for (const char end : {'A', 'B'}) {
    const EndCondition& c = end == 'A' ? end_a : end_b;
    const double theta = end == 'A' ? 0.0 : std::numbers::pi;
    const int span = end == 'A' ? p : n - 1;
    const Eigen::MatrixXd ders = ders_basis_funs(span, theta, p, 2, space.knots);
    const std::optional<double> given[3] = {c.r, c.dr, c.ddr};
    for (int order = 0; order < 3; ++order) {
      if (!given[order]) continue;
      if (!std::isfinite(*given[order]))
        throw InputError("synthesis: end " + std::string(1, end) + " " +
                         EndConstraint{end, order, 0.0, {}}.name() + " must be finite");
      Eigen::RowVectorXd on_ordinates = Eigen::RowVectorXd::Zero(n);
      on_ordinates.segment(span - p, p + 1) = ders.row(order);
      out.imposed.push_back({end, order, *given[order], on_ordinates * space.map});
    }
  }
  if (depth) {
    if (!(std::isfinite(*depth) && *depth > 0.0))
      throw InputError("synthesis: depth R(π/2) " + value_text(*depth) + " mm, expected > 0");
    const double theta = std::numbers::pi / 2;
    const int span = find_span(p, space.knots, n, theta);
    Eigen::RowVectorXd on_ordinates = Eigen::RowVectorXd::Zero(n);
    on_ordinates.segment(span - p, p + 1) = ders_basis_funs(span, theta, p, 0, space.knots).row(0);
    out.imposed.push_back({'M', 0, *depth, on_ordinates * space.map});
  }

  // Accept each condition whose row is independent of the accepted ones; a dependent one must
  // agree with the value the accepted ones force on it.
  std::vector<const EndConstraint*> accepted;
  for (const EndConstraint& c : out.imposed) {
    const int k = static_cast<int>(accepted.size());
    Eigen::MatrixXd At(space.unknowns(), k);
    Eigen::VectorXd b(k);
    for (int i = 0; i < k; ++i) {
      At.col(i) = accepted[i]->row.transpose();
      b(i) = accepted[i]->value;
    }
    Eigen::VectorXd alpha = Eigen::VectorXd::Zero(k);
    if (k > 0) alpha = At.colPivHouseholderQr().solve(c.row.transpose());
    const double residual = (At * alpha - c.row.transpose()).norm();
    if (residual > 1e-10 * c.row.norm()) {
      accepted.push_back(&c);
      continue;
    }
    const double forced = alpha.dot(b);
    if (std::abs(forced - c.value) > 1e-9 * (std::abs(c.value) + std::abs(forced) + length_unit)) {
      std::string before;
      for (const EndConstraint* a : accepted) before += (before.empty() ? "" : ", ") + a->name();
      throw InputError("synthesis: contradictory end conditions: " + c.name() + " = " +
                       value_text(c.value) + " " + unit_of(c.order) + ", but the B-spline space (" +
                       space_text(space) + ")" + (before.empty() ? "" : " with " + before) +
                       " forces " + c.name() + " = " + value_text(forced) + " " + unit_of(c.order));
    }
  }

  const int rank = static_cast<int>(accepted.size());
  out.free_parameters = space.unknowns() - rank;
  if (out.free_parameters < 1)
    throw InputError("synthesis: too few degrees of freedom: " + std::to_string(space.unknowns()) +
                     " unknowns (" + space_text(space) + ") and " + std::to_string(rank) +
                     " independent end conditions leave " + std::to_string(out.free_parameters) +
                     " free; use more ordinates or fewer end conditions");
  out.rows.resize(rank, space.unknowns());
  out.values.resize(rank);
  for (int i = 0; i < rank; ++i) {
    out.rows.row(i) = accepted[i]->row;
    out.values(i) = accepted[i]->value;
  }
  return out;
}

}  // namespace polarform
