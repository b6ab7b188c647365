#include "designers/convert/conversion_error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "designers/convert/refined_maximum.h"

namespace polarform {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// ψ wrapped into R's domain (closed functions) or clamped to it (open ones).
double into_domain(const PolarFunction& R, double psi) {
  if (R.closed()) {
    psi = R.start + std::fmod(psi - R.start, kTwoPi);
    return psi < R.start ? psi + kTwoPi : psi;
  }
  return std::clamp(psi, R.start, R.end);
}

}  // namespace

int samples_per_span(int degree) { return std::min(32, 4 * (degree + 1)); }

double radial_error_at(const NurbsCurve2d& C, const PolarFunction& R, double u, double near,
                       double* psi_out) {
  const Eigen::Vector2d p = C(u);
  const double psi = polar_angle_near(p.x(), p.y(), near);
  if (psi_out) *psi_out = psi;
  return std::abs(p.norm() - R(into_domain(R, psi)));
}

ProfileError profile_error(const NurbsCurve2d& C, const PolarFunction& R, double u0, double u1,
                           int samples) {
  // The grid: C's knot spans within [u0, u1], since the error oscillates span by span (a minimax
  // refit's nearly equally), each sampled and every local maximum refined.
  std::vector<double> grid{u0};
  for (double k : C.knots())
    if (k > grid.back() && k < u1) grid.push_back(k);
  grid.push_back(u1);
  const int spans = static_cast<int>(grid.size()) - 1;
  // The base circles are parametrised by angle, so u is a good guess of the polar angle.
  const Maximum m =
      refined_maximum([&](double u) { return radial_error_at(C, R, u, u); }, grid,
                      std::max(samples_per_span(C.degree()), samples / spans), 2 * spans + 4);
  ProfileError out;
  out.max_radial = m.value;
  double psi;
  radial_error_at(C, R, m.at, m.at, &psi);
  out.at_angle = into_domain(R, psi);
  double d[2];
  R.derivatives(out.at_angle, 1, d);
  // A radial offset δ moves the point by δ·R/√(R² + R'²) along the normal of r = R(ψ) (the
  // factor, at most 1, taken first so that round-off cannot lift it past δ).
  out.max_normal = m.value * std::min(1.0, std::abs(d[0]) / std::hypot(d[0], d[1]));
  return out;
}

double max_tangent_jump(const NurbsCurve2d& C, const std::vector<double>& junctions) {
  double worst = 0.0;
  for (double u : junctions) {
    const double h = 1e-7 * (C.back() - C.front());
    // One-sided tangents, extrapolated to u from inside each span (second order).
    const auto left = C.derivatives(u - h, 2), right = C.derivatives(u + h, 2);
    const Eigen::Vector2d tl = left[1] + h * left[2], tr = right[1] - h * right[2];
    const double cross = tl.x() * tr.y() - tl.y() * tr.x();
    worst = std::max(worst, std::abs(std::atan2(cross, tl.dot(tr))));
  }
  return worst;
}

}  // namespace polarform
