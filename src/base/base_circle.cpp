#include "src/base/base_circle.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "src/base/arc_curves.h"
#include "src/error.h"

namespace polarform {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Validates the breakpoints (sorted, arc sweeps within the kind's limit, total <= 2π) and snaps a
// total within kAngleSlack of 2π to a closed circle; returns whether it is closed.
bool check_breakpoints(ArcKind kind, std::vector<double>& theta) {
  if (theta.size() < 2)
    throw InputError("base circle breakpoints: " + std::to_string(theta.size()) +
                     " given, expected at least 2 (one arc)");
  for (std::size_t j = 0; j < theta.size(); ++j)
    if (!std::isfinite(theta[j]))
      throw InputError("base circle breakpoint " + std::to_string(j) + " is not finite");
  const double total = theta.back() - theta.front();
  if (total > kTwoPi + kAngleSlack)
    throw InputError("base circle breakpoints: total angle " + std::to_string(total) +
                     ", expected at most 2*pi");
  const bool closed = std::abs(total - kTwoPi) <= kAngleSlack;
  if (closed) theta.back() = theta.front() + kTwoPi;
  const bool rqb = kind == ArcKind::rqb;
  for (std::size_t j = 0; j + 1 < theta.size(); ++j) {
    const double sweep = theta[j + 1] - theta[j];
    if (!(sweep > 0.0))
      throw InputError("base circle breakpoints: not strictly increasing at index " +
                       std::to_string(j + 1));
    if (rqb ? sweep >= std::numbers::pi : sweep > std::numbers::pi + 2.0 * kAngleSlack)
      throw InputError("base circle arc " + std::to_string(j) + ": sweep " + std::to_string(sweep) +
                       (rqb ? ", expected < pi for an RQB arc" : ", expected <= pi for a quartic arc"));
  }
  return closed;
}

// Index j of the arc with values[j] <= x < values[j+1] (the last arc also holds its end).
int arc_at(const std::vector<double>& values, double x) {
  const auto it = std::upper_bound(values.begin() + 1, values.end() - 1, x);
  return static_cast<int>(it - values.begin()) - 1;
}

}  // namespace

BaseCircle::BaseCircle(ArcKind kind, std::vector<double> breakpoints, AlphaRule rule,
                       ArcParametrization param)
    : kind_(kind), rule_(rule), param_(param), theta_(std::move(breakpoints)) {
  closed_ = check_breakpoints(kind_, theta_);
  const int k = arcs();
  const int degree = kind_ == ArcKind::rqb ? 2 : 4;
  for (int j = 0; j <= k; ++j) u_.push_back(param_ == ArcParametrization::angle ? theta_[j] : j);
  // Bae 2002, eq. (2.3): Bezier arcs joined at interior knots of multiplicity = degree.
  std::vector<double> interior;
  Eigen::MatrixXd h(3, k * degree + 1);
  for (int j = 0; j < k; ++j) {
    const double half = (theta_[j + 1] - theta_[j]) / 2.0;
    alpha_.push_back(kind_ == ArcKind::quartic ? quartic_alpha(half, rule_) : 1.0);
    h.middleCols(j * degree, degree + 1) =
        arc_homogeneous_points(kind_, theta_[j], theta_[j + 1], alpha_[j]);
    if (j > 0) interior.insert(interior.end(), degree, u_[j]);
  }
  curve_ = NurbsCurve2d(BSpline(degree, clamped_knots(degree, u_.front(), u_.back(), interior),
                                std::move(h)));
}

BaseCircle BaseCircle::equal_arcs(ArcKind kind, double start, double end, int arcs,
                                  AlphaRule rule, ArcParametrization param) {
  if (arcs < 1)
    throw InputError("base circle arcs: " + std::to_string(arcs) + ", expected at least 1");
  std::vector<double> theta(arcs + 1);
  for (int j = 0; j < arcs; ++j) theta[j] = start + (end - start) * j / arcs;
  theta[arcs] = end;
  return BaseCircle(kind, std::move(theta), rule, param);
}

BaseCircle BaseCircle::fewest_arcs(ArcKind kind, double start, double end, AlphaRule rule,
                                   ArcParametrization param) {
  return with_max_sweep(kind, start, end, std::numbers::pi, rule, param);
}

BaseCircle BaseCircle::with_max_sweep(ArcKind kind, double start, double end, double max_sweep,
                                      AlphaRule rule, ArcParametrization param) {
  const double total = end - start;
  if (!(total > 0.0 && total <= kTwoPi + kAngleSlack))
    throw InputError("base circle range [" + std::to_string(start) + ", " + std::to_string(end) +
                     "]: expected 0 < end - start <= 2*pi");
  if (!(max_sweep > 0.0 && max_sweep <= std::numbers::pi))
    throw InputError("base circle max_sweep " + std::to_string(max_sweep) +
                     ": expected 0 < max_sweep <= pi");
  // ceil(total / max_sweep) arcs, one more when an RQB arc would reach π.
  int arcs = std::max(1, static_cast<int>(std::ceil(total / max_sweep - 1e-12)));
  if (kind == ArcKind::rqb && total / arcs >= std::numbers::pi) ++arcs;
  return equal_arcs(kind, start, end, arcs, rule, param);
}

double BaseCircle::alpha(int arc) const {
  if (arc < 0 || arc >= arcs())
    throw InputError("base circle arc index " + std::to_string(arc) + ": expected 0.." +
                     std::to_string(arcs() - 1));
  return alpha_[arc];
}

// Bae 2002, eqs. (2.7)–(2.8); quartic arcs through the inverse of (5.3).
double BaseCircle::parameter(double theta) const {
  const double t0 = theta_.front(), t1 = theta_.back();
  if (closed_) {
    theta -= kTwoPi * std::floor((theta - t0) / kTwoPi);
  } else if (!(theta >= t0 - kAngleSlack && theta <= t1 + kAngleSlack)) {
    throw InputError("base circle angle theta " + std::to_string(theta) + ": expected a value in [" +
                     std::to_string(t0) + ", " + std::to_string(t1) + "]");
  }
  theta = std::clamp(theta, t0, t1);
  const int j = arc_at(theta_, theta);
  const double half = (theta_[j + 1] - theta_[j]) / 2.0, xi = theta - theta_[j];
  const double eta = kind_ == ArcKind::rqb ? rqb_arc_parameter(half, xi)
                                           : quartic_arc_parameter(half, alpha_[j], xi);
  return u_[j] + (u_[j + 1] - u_[j]) * eta;
}

void BaseCircle::parameters(const double* theta, double* u, std::size_t n) const {
  for (std::size_t i = 0; i < n; ++i) u[i] = parameter(theta[i]);
}

double BaseCircle::angle(double u) const {
  if (!(u >= u_.front() - kAngleSlack && u <= u_.back() + kAngleSlack))
    throw InputError("base circle parameter u " + std::to_string(u) + ": expected a value in [" +
                     std::to_string(u_.front()) + ", " + std::to_string(u_.back()) + "]");
  u = std::clamp(u, u_.front(), u_.back());
  const int j = arc_at(u_, u);
  const double half = (theta_[j + 1] - theta_[j]) / 2.0;
  const double eta = std::min(1.0, (u - u_[j]) / (u_[j + 1] - u_[j]));
  const double xi = kind_ == ArcKind::rqb ? rqb_arc_angle(half, eta)
                                          : quartic_arc_angle(half, alpha_[j], eta);
  return theta_[j] + xi;
}

}  // namespace polarform
