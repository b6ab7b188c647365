#include "designers/cam/follower_dynamics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

void check(bool ok, const std::string& what, double value, const char* expected) {
  if (!ok)
    throw InputError("follower dynamics: " + what + " " + number_text(value) + ", expected " +
                     expected);
}

// The smallest ω > 0 with m·a·1e-3·ω² + c·v·ω + (k·s + F₀) = 0 at one angle, if any (F falls below
// zero only where the inertia or the damping pulls the follower off).
std::optional<double> losing_speed(double mass_a, double damping_v, double spring) {
  if (spring < 0) return 0.0;  // no force holds it even at rest
  const double A = mass_a, B = damping_v, C = spring;
  if (A == 0) {
    if (B < 0) return C / -B;
    return std::nullopt;
  }
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return std::nullopt;
  const double r = std::sqrt(disc);
  double best = std::numeric_limits<double>::infinity();
  for (const double w : {(-B - r) / (2 * A), (-B + r) / (2 * A)})
    if (w > 0) best = std::min(best, w);
  if (!std::isfinite(best)) return std::nullopt;
  return best;
}

// The follower's equation in its own coordinate q: Q = M q̈ + C q̇ + K q + Q₀ with q̈ = ω² q'', q̇ = ω
// q'
// (' per radian of cam angle); the contact force F = Q (translating) or Q / lever (arm), the
// camshaft torque T = Q q'·torque_scale.
struct GeneralisedLoad {
  double M, C, K,
      Q0;  // translating: kg→N·s²/mm (m·1e-3), N·s/mm, N/mm, N; arm: kg·m², N·m·s/rad, N·m/rad, N·m
  double q_scale;       // q per unit of s: 1 (mm), π/180 (° → rad)
  double torque_scale;  // Q·q' → N·m: 1e-3 (N·mm), 1 (N·m)
};

GeneralisedLoad generalised(const FollowerLoad& l) {
  if (l.arm)
    return {l.inertia,        l.torsion_damping,      l.torsion_rate,
            l.preload_torque, std::numbers::pi / 180, 1.0};
  return {l.mass * 1e-3, l.damping, l.spring_rate, l.preload, 1.0, 1e-3};
}

}  // namespace

double line_contact_stress(double force, double width, double r1, double r2, double youngs,
                           double poisson) {
  const double curvature =
      (std::isfinite(r1) && r1 != 0 ? 1 / r1 : 0.0) + (std::isfinite(r2) && r2 != 0 ? 1 / r2 : 0.0);
  if (!(force > 0) || !(curvature > 0)) return 0.0;
  const double compliance = 2 * (1 - poisson * poisson) / youngs;
  return std::sqrt(force * curvature / (std::numbers::pi * width * compliance));
}

FollowerDynamics follower_dynamics(const std::vector<MotionSample>& motion, double rpm,
                                   double roller_radius, const FollowerLoad& load,
                                   double second_roller_radius) {
  check(load.mass >= 0 && std::isfinite(load.mass), "mass", load.mass, ">= 0 kg");
  check(load.spring_rate >= 0 && std::isfinite(load.spring_rate), "spring rate", load.spring_rate,
        ">= 0 N/mm");
  check(load.preload >= 0 && std::isfinite(load.preload), "preload", load.preload, ">= 0 N");
  check(load.damping >= 0 && std::isfinite(load.damping), "damping", load.damping, ">= 0 N·s/mm");
  check(load.inertia >= 0 && std::isfinite(load.inertia), "inertia", load.inertia, ">= 0 kg·m²");
  check(load.torsion_rate >= 0 && std::isfinite(load.torsion_rate), "torsion rate",
        load.torsion_rate, ">= 0 N·m/rad");
  check(load.preload_torque >= 0 && std::isfinite(load.preload_torque), "preload torque",
        load.preload_torque, ">= 0 N·m");
  check(load.torsion_damping >= 0 && std::isfinite(load.torsion_damping), "torsion damping",
        load.torsion_damping, ">= 0 N·m·s/rad");
  check(load.contact_width >= 0 && std::isfinite(load.contact_width), "contact width",
        load.contact_width, ">= 0 mm");
  check(load.youngs_modulus > 0 && std::isfinite(load.youngs_modulus), "Young's modulus",
        load.youngs_modulus, "> 0 MPa");
  check(load.poisson_ratio >= 0 && load.poisson_ratio < 0.5, "Poisson ratio", load.poisson_ratio,
        "in [0, 0.5)");
  const double w = rpm * 2 * std::numbers::pi / 60;  // rad/s
  const GeneralisedLoad g = generalised(load);
  FollowerDynamics out;
  double fastest = std::numeric_limits<double>::infinity();
  for (const MotionSample& m : motion) {
    if (load.arm)
      check(m.lever > 0, "lever of the contact force about the pivot [mm]", m.lever, "> 0");
    // Per unit of the contact force: 1 (translating), 1000/lever (arm: N·m over a lever in mm).
    const double per_load = load.arm ? 1e3 / m.lever : 1.0;
    const double q = m.s * g.q_scale, dq = m.v * g.q_scale;
    const double inertia = g.M * m.a * g.q_scale * per_load, damping = g.C * dq * per_load;
    const double spring = (g.K * q + g.Q0) * per_load;
    DynamicsSample d;
    d.theta = m.theta;
    d.force = inertia * w * w + damping * w + spring;
    d.torque = d.force / per_load * dq * g.torque_scale;  // T = Q dq/dθ
    if (load.contact_width > 0)
      d.contact_stress =
          line_contact_stress(d.force, load.contact_width, roller_radius, m.contour_radius,
                              load.youngs_modulus, load.poisson_ratio);
    if (second_roller_radius > 0) {
      if (load.arm)
        check(m.second_lever > 0, "lever of the second roller's contact force about the pivot [mm]",
              m.second_lever, "> 0");
      const double q_load = d.force / per_load;  // Q
      d.second_force = std::max(0.0, -q_load * (load.arm ? 1e3 / m.second_lever : 1.0));
      if (load.contact_width > 0)
        d.second_stress =
            line_contact_stress(d.second_force, load.contact_width, second_roller_radius,
                                m.second_contour_radius, load.youngs_modulus, load.poisson_ratio);
      if (out.samples.empty() || d.second_force > out.largest_second_force.second_force)
        out.largest_second_force = d;
      if (out.samples.empty() || d.second_stress > out.largest_second_stress.second_stress)
        out.largest_second_stress = d;
    }
    if (out.samples.empty() || d.force < out.least_force.force) out.least_force = d;
    if (out.samples.empty() || std::abs(d.torque) > std::abs(out.largest_torque.torque))
      out.largest_torque = d;
    if (out.samples.empty() || d.contact_stress > out.largest_stress.contact_stress)
      out.largest_stress = d;
    if (const auto speed = losing_speed(inertia, damping, spring))
      fastest = std::min(fastest, *speed);
    // The rate that makes F = 0 here at this speed, with the same preload.
    if (q > 0)
      out.min_spring_rate = std::max(
          out.min_spring_rate, -(inertia * w * w + damping * w + g.Q0 * per_load) / (q * per_load));
    out.samples.push_back(d);
  }
  out.conjugate = second_roller_radius > 0;
  out.jumps = !out.conjugate && out.least_force.force < 0;
  if (!out.conjugate && std::isfinite(fastest))
    out.jump_rpm = fastest * 60 / (2 * std::numbers::pi);
  return out;
}

}  // namespace polarform
