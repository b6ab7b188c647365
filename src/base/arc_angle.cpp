#include "src/base/arc_angle.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "src/error.h"

namespace polarform {

namespace {

void check_half_angle(double half_angle) {
  if (!(half_angle > 0.0 && half_angle <= std::numbers::pi / 2 + kAngleSlack))
    throw InputError("arc half_angle " + std::to_string(half_angle) +
                     ": expected 0 < half_angle <= pi/2");
}

void check_alpha(double alpha) {
  if (!(alpha > 0.0 && std::isfinite(alpha)))
    throw InputError("quartic arc alpha " + std::to_string(alpha) + ": expected a finite alpha > 0");
}

double clamped(double x, double lo, double hi, const char* field) {
  if (!(x >= lo - kAngleSlack && x <= hi + kAngleSlack))
    throw InputError(std::string(field) + " " + std::to_string(x) + ": expected a value in [" +
                     std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return std::clamp(x, lo, hi);
}

// s(η) of the quartic arc; Bae 2002, eq. (5.3).
double quartic_s(double alpha, double eta) {
  const double beta = 1.0 - alpha;
  return (alpha * eta + beta * eta * eta) / (1.0 - 2.0 * beta * eta * (1.0 - eta));
}

}  // namespace

// Bae 2002, eq. (5.2).
double printed_alpha(double half_angle) {
  check_half_angle(half_angle);
  const double c = std::cos(half_angle / 5.0);
  return (4.0 - 2.0 * c * c * c + c) / (-1.0 + 8.0 * c * c * c - 4.0 * c);
}

// DESIGN.md §4.3 (minimax α: exactly uniform at the fitted equioscillation point η = k).
double minimax_alpha(double half_angle) {
  check_half_angle(half_angle);
  const double phi2 = half_angle * half_angle;
  const double k = (3.0 - std::sqrt(5.0)) / 4.0 + 2.2736e-3 * phi2 - 2.1349e-5 * phi2 * phi2;
  const double q = k / (1.0 - k);
  const double R = std::sin((1.0 - k) * half_angle) / std::sin(k * half_angle);
  return (1.0 - R * q * q) / (q * (R - 1.0));
}

double quartic_alpha(double half_angle, AlphaRule rule) {
  return rule == AlphaRule::minimax ? minimax_alpha(half_angle) : printed_alpha(half_angle);
}

// Bae 2002, eq. (2.7), pole-free form of DESIGN.md §4.2:
// η = sin(ξ/2) / (sin φ cos(ξ/2) + (1 − cos φ) sin(ξ/2)), with 1 − cos φ = 2 sin²(φ/2).
double rqb_arc_parameter(double half_angle, double xi) {
  check_half_angle(half_angle);
  xi = clamped(xi, 0.0, 2.0 * half_angle, "arc angle xi");
  const double S = std::sin(xi / 2.0), C = std::cos(xi / 2.0);
  const double h = std::sin(half_angle / 2.0);
  return S / (std::sin(half_angle) * C + 2.0 * h * h * S);
}

// Blanc & Schlick 1996 (Bae 2002, eq. (5.3) with s = η): ξ = 2 atan(η sin φ / (1 − η(1 − cos φ))).
double rqb_arc_angle(double half_angle, double eta) {
  check_half_angle(half_angle);
  eta = clamped(eta, 0.0, 1.0, "arc parameter eta");
  const double h = std::sin(half_angle / 2.0);
  return 2.0 * std::atan2(eta * std::sin(half_angle), 1.0 - eta * 2.0 * h * h);
}

// Bae 2002, eq. (5.3).
double quartic_arc_angle(double half_angle, double alpha, double eta) {
  check_alpha(alpha);
  eta = clamped(eta, 0.0, 1.0, "arc parameter eta");
  return rqb_arc_angle(half_angle, quartic_s(alpha, eta));
}

// Inverse of Bae 2002, eq. (5.3): s(η) = s is β(2s − 1)η² − (2sβ + α)η + s = 0 with β = 1 − α.
// The arc is symmetric, ξ(1 − η) = 2φ − ξ(η), so only s ≤ 1/2 is solved, where 2sβ + α > 0 and
// the root in [0, 1] is 2s / (2sβ + α + √disc) (no cancellation, no division by β(2s − 1)).
double quartic_arc_parameter(double half_angle, double alpha, double xi) {
  check_alpha(alpha);
  check_half_angle(half_angle);
  xi = clamped(xi, 0.0, 2.0 * half_angle, "arc angle xi");
  if (xi > half_angle) return 1.0 - quartic_arc_parameter(half_angle, alpha, 2.0 * half_angle - xi);
  const double s = rqb_arc_parameter(half_angle, xi);
  const double beta = 1.0 - alpha;
  const double b = 2.0 * s * beta + alpha;
  const double disc = std::max(0.0, b * b - 4.0 * beta * (2.0 * s - 1.0) * s);
  return 2.0 * s / (b + std::sqrt(disc));
}

}  // namespace polarform
