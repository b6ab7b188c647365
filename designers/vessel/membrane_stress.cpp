#include "designers/vessel/membrane_stress.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "designers/vessel/polar_curvature.h"
#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/gauss_legendre.h"

namespace polarform {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

void check_positive(double value, const char* name, const char* unit) {
  if (!(value > 0.0 && std::isfinite(value)))
    throw InputError(std::string("membrane stresses: ") + name + " " + to_text(value) + " " + unit +
                     ", expected > 0");
}

// How far from a joint of the meridian its one-sided values are taken, rad.
constexpr double kJointSide = 1e-10;

// Golden-section search for the extremum of f in [a, b] (min if `minimum`, else max).
double golden_extremum(const std::function<double(double)>& f, double a, double b, bool minimum) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  const auto better = [&](double x, double y) { return minimum ? f(x) < f(y) : f(x) > f(y); };
  double c = b - g * (b - a), d = a + g * (b - a);
  for (int k = 0; k < 80 && b - a > 1e-13; ++k) {
    if (better(c, d)) {
      b = d;
      d = c;
      c = b - g * (b - a);
    } else {
      a = c;
      c = d;
      d = a + g * (b - a);
    }
  }
  return 0.5 * (a + b);
}

// The head's sample angles over [0, π/2]: `count` equal steps, both sides of every joint of the
// meridian (where curvature, and with it the hoop stress, jumps: the closed-form extremes of the
// standard heads), and every interior extremum of either stress located by golden section — so
// that the profile's extremes are the stresses' own, not a grid's.
std::vector<double> head_angles(const PolarFunction& head, const VesselLoad& load, int count,
                                double end) {
  std::vector<double> angles;
  if (end == 0.0) return {0.0};  // the junction only (a flat head)
  for (int i = 0; i < count; ++i) angles.push_back(i == count - 1 ? end : end * i / (count - 1));
  std::vector<double> joints;
  for (const double b : head.breakpoints)
    if (b > kJointSide && b < end - kJointSide) joints.push_back(b);
  for (const double b : joints) {
    angles.push_back(b - kJointSide);
    angles.push_back(b + kJointSide);
  }
  std::sort(angles.begin(), angles.end());
  const auto across_joint = [&](double a, double b) {
    return std::any_of(joints.begin(), joints.end(), [&](double j) { return a < j && j < b; });
  };
  const auto stress = [&](bool hoop) {
    return [&, hoop](double theta) {
      const PrincipalRadii r = principal_radii(head, theta);
      const MembraneForces f = membrane_forces(load.pressure, r.kappa1, r.r2);
      return hoop ? f.hoop : f.meridional;
    };
  };
  std::vector<double> extrema;
  const double noise = 1e-9 * load.pressure * load.radius;  // N/mm: rounding, not an extremum
  for (const bool hoop : {true, false}) {
    const std::function<double(double)> f = stress(hoop);
    std::vector<double> values;  // f at every angle, once
    for (const double theta : angles) values.push_back(f(theta));
    for (std::size_t i = 1; i + 1 < angles.size(); ++i) {
      const double a = angles[i - 1], b = angles[i + 1];
      if (across_joint(a, b)) continue;
      const double fa = values[i - 1], fm = values[i], fb = values[i + 1];
      if (fm < std::min(fa, fb) - noise) extrema.push_back(golden_extremum(f, a, b, true));
      if (fm > std::max(fa, fb) + noise) extrema.push_back(golden_extremum(f, a, b, false));
    }
  }
  angles.insert(angles.end(), extrema.begin(), extrema.end());
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  return angles;
}

}  // namespace

// ∫ √(R² + R'²) dθ, 4-point Gauss–Legendre on each interval (Abramowitz & Stegun 25.4.30).
double arc_length(const PolarFunction& R, double a, double b, int intervals) {
  return integrate_gauss_legendre(
      [&](double theta) {
        double d[2];
        R.derivatives(theta, 1, d);
        return std::hypot(d[0], d[1]);
      },
      a, b, intervals);
}

// r1 = 1/κ (DESIGN §4.4); r2 = x / n_x with the outward unit normal
// n = (R' sin θ + R cos θ, R sin θ − R' cos θ) / √(R² + R'²).
PrincipalRadii principal_radii(const PolarFunction& head, double theta) {
  double d[3];
  head.derivatives(theta, 2, d);
  const double kappa1 = polar_curvature(d[0], d[1], d[2]);
  // The apex: a smooth one's r2 is its r1; at a cone point (R' ≠ 0) r2 = x/n_x vanishes with x.
  if (theta == kHalfPi) return {kappa1, std::abs(d[1]) > 1e-12 * d[0] ? 0.0 : 1.0 / kappa1};
  const double c = std::cos(theta), s = std::sin(theta);
  return {kappa1, d[0] * c * std::hypot(d[0], d[1]) / (d[1] * s + d[0] * c)};
}

// Membrane forces of a shell of revolution under internal pressure (Timoshenko &
// Woinowsky-Krieger, Theory of Plates and Shells, 1959, ch. 14).
MembraneForces membrane_forces(double pressure, double kappa1, double r2) {
  return {pressure * r2 / 2, pressure * r2 * (1 - kappa1 * r2 / 2)};
}

void check_vessel_load(const VesselLoad& load) {
  check_positive(load.radius, "radius", "mm");
  check_positive(load.length, "length", "mm");
  check_positive(load.thickness, "thickness", "mm");
  check_positive(load.pressure, "pressure", "MPa");
}

StressProfile membrane_stresses(const PolarFunction& head, const VesselLoad& load, int samples,
                                double membrane_end) {
  check_vessel_load(load);
  if (samples < 2)
    throw InputError("membrane stresses: " + std::to_string(samples) + " samples, expected >= 2");
  if (!(membrane_end >= 0.0 && membrane_end <= kHalfPi))
    throw InputError("membrane stresses: membrane end " + to_text(membrane_end) +
                     " rad, expected in [0, π/2]");

  const auto sample = [&](double s, double theta, double rho, double z, PrincipalRadii radii,
                          bool cylinder) {
    const MembraneForces f = membrane_forces(load.pressure, radii.kappa1, radii.r2);
    return StressSample{s, theta, rho, z, radii, f, f.meridional / load.thickness,
                        f.hoop / load.thickness, cylinder};
  };
  StressProfile out;
  const PrincipalRadii cylinder{0.0, load.radius};
  out.samples.push_back(sample(-load.length / 2, 0.0, load.radius, -load.length / 2, cylinder, true));
  out.samples.push_back(sample(0.0, 0.0, load.radius, 0.0, cylinder, true));
  double s = 0.0;
  for (const double theta : head_angles(head, load, samples, membrane_end)) {
    if (out.samples.size() > 2) s += arc_length(head, out.samples.back().theta, theta);
    const double r = head(theta);
    out.samples.push_back(sample(s, theta, r * std::cos(theta), r * std::sin(theta),
                                 principal_radii(head, theta), false));
  }

  // Runs of compressive hoop samples, their ends bisected to N_θ = 0 between grid angles.
  const auto hoop = [&](double theta) {
    const PrincipalRadii r = principal_radii(head, theta);
    return membrane_forces(load.pressure, r.kappa1, r.r2).hoop;
  };
  const auto root = [&](double a, double b) {  // hoop(a), hoop(b) of opposite sign
    const bool a_negative = hoop(a) < 0;
    for (int k = 0; k < 60; ++k) {
      const double m = 0.5 * (a + b);
      if ((hoop(m) < 0) == a_negative)
        a = m;
      else
        b = m;
    }
    return 0.5 * (a + b);
  };
  const auto head_begin = out.samples.begin() + 2;
  for (auto it = head_begin; it != out.samples.end();) {
    if (it->hoop_stress >= 0) {
      ++it;
      continue;
    }
    auto end = it;
    CompressiveBand band;
    band.min_hoop_stress = it->hoop_stress;
    while (end != out.samples.end() && end->hoop_stress < 0) {
      band.min_hoop_stress = std::min(band.min_hoop_stress, end->hoop_stress);
      ++end;
    }
    band.theta_from = it == head_begin ? 0.0 : root((it - 1)->theta, it->theta);
    band.theta_to = end == out.samples.end() ? membrane_end : root((end - 1)->theta, end->theta);
    band.s_from = it == head_begin ? 0.0
                                   : (it - 1)->s + arc_length(head, (it - 1)->theta, band.theta_from);
    band.s_to = (end - 1)->s + arc_length(head, (end - 1)->theta, band.theta_to);
    out.compressive_hoop.push_back(band);
    it = end;
  }
  return out;
}

}  // namespace polarform
