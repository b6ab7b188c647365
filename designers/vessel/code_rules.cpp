#include "designers/vessel/code_rules.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

// A formula of the code: the thickness it requires for P and the pressure it allows for t, both on
// corroded dimensions and without the corrosion allowance.
struct Rule {
  std::string name;
  double thickness = 0.0;
  double pressure = 0.0;
};

// S, E, P and the corroded nominal thickness t − c.
struct Load {
  double S = 0.0, E = 0.0, P = 0.0, t = 0.0, c = 0.0;
};

std::string quantity(const std::string& name, double value, const char* unit) {
  return name + " = " + number_text(value) + (*unit ? " " : "") + unit;
}

void require(bool ok, const std::string& what, const std::string& expected) {
  if (!ok) throw InputError("code rules: " + what + ", expected " + expected);
}

void require_positive(double value, const std::string& name, const char* unit) {
  require(value > 0.0 && std::isfinite(value), quantity(name, value, unit), "> 0");
}

void require_efficiency(double value, const std::string& name) {
  require(value > 0.0 && value <= 1.0, quantity(name, value, ""), "in (0, 1]");
}

// P below the pressure at which the formula's thickness denominator vanishes.
void require_pressure_below(const Load& k, double limit, const std::string& limit_text,
                            const std::string& formula) {
  require(k.P < limit, quantity("design pressure P", k.P, "MPa"),
          "< " + limit_text + " = " + number_text(limit) + " MPa for " + formula);
}

void warn_above(std::vector<std::string>& warnings, const std::string& paragraph,
                const std::string& what, double value, const std::string& limit_text, double limit,
                const char* unit) {
  if (value > limit)
    warnings.push_back(paragraph + ": " + quantity(what, value, unit) + " exceeds " + limit_text +
                       " = " + number_text(limit) + (*unit ? " " : "") + unit);
}

bool close_to(double value, double target) {
  return std::abs(value - target) <= 1e-9 * std::abs(target);
}

std::vector<Rule> rules(const CylindricalShell& shell, const Load& k,
                        std::vector<std::string>& warnings) {
  require_positive(shell.inside_radius, "cylindrical shell: inside radius R", "mm");
  const double Ec = shell.circumferential_joint_efficiency.value_or(k.E);
  require_efficiency(Ec, "cylindrical shell: circumferential joint efficiency");
  const double R = shell.inside_radius + k.c, SE = k.S * k.E, SEc = k.S * Ec;
  require_pressure_below(k, SE / 0.6, "S·E/0.6", "UG-27(c)(1)");
  warn_above(warnings, "UG-27(c)(1)", "design pressure P", k.P, "0.385·S·E", 0.385 * SE, "MPa");
  warn_above(warnings, "UG-27(c)(2)", "design pressure P", k.P, "1.25·S·E", 1.25 * SEc, "MPa");
  warn_above(warnings, "UG-27(c)", "corroded thickness t − c", k.t, "R/2", R / 2, "mm");
  // UG-27(c)(1): t = PR/(SE − 0.6P), P = SEt/(R + 0.6t).
  Rule circumferential{"UG-27(c)(1) cylinder, circumferential stress", k.P * R / (SE - 0.6 * k.P),
                       SE * k.t / (R + 0.6 * k.t)};
  // UG-27(c)(2): t = PR/(2SE + 0.4P), P = 2SEt/(R − 0.4t); t tends to 2.5 R as P grows, so a
  // thicker wall is never limited by the longitudinal stress.
  Rule longitudinal{
      "UG-27(c)(2) cylinder, longitudinal stress", k.P * R / (2 * SEc + 0.4 * k.P),
      k.t < 2.5 * R ? 2 * SEc * k.t / (R - 0.4 * k.t) : std::numeric_limits<double>::infinity()};
  return {circumferential, longitudinal};
}

// The formed heads' thickness denominators 2SE − 0.2P (SE − 0.1P for UG-32(e)) vanish at P = 10 SE.
void require_head_pressure(const Load& k, const std::string& formula) {
  require_pressure_below(k, 10 * k.S * k.E, "10·S·E", formula);
}

std::vector<Rule> rules(const HemisphericalHead& head, const Load& k,
                        std::vector<std::string>& warnings) {
  require_positive(head.inside_radius, "hemispherical head: inside radius L", "mm");
  const double L = head.inside_radius + k.c, SE = k.S * k.E;
  const std::string name = "UG-32(f) hemispherical";
  require_head_pressure(k, name);
  // UG-32(f) applies UG-27(d)'s limits: t <= 0.356 L or P <= 0.665 SE.
  warn_above(warnings, "UG-32(f)", "design pressure P", k.P, "0.665·S·E", 0.665 * SE, "MPa");
  warn_above(warnings, "UG-32(f)", "corroded thickness t − c", k.t, "0.356·L", 0.356 * L, "mm");
  // UG-32(f): t = PL/(2SE − 0.2P), P = 2SEt/(L + 0.2t).
  return {{name, k.P * L / (2 * SE - 0.2 * k.P), 2 * SE * k.t / (L + 0.2 * k.t)}};
}

std::vector<Rule> rules(const EllipsoidalHead& head, const Load& k,
                        std::vector<std::string>& warnings) {
  require_positive(head.inside_diameter, "ellipsoidal head: inside diameter D", "mm");
  require_positive(head.inside_depth, "ellipsoidal head: inside depth h", "mm");
  const double D = head.inside_diameter + 2 * k.c, h = head.inside_depth + k.c, SE = k.S * k.E;
  if (close_to(head.inside_diameter / (2 * head.inside_depth), 2.0)) {
    const std::string name = "UG-32(d) 2:1 ellipsoidal";
    require_head_pressure(k, name);
    // UG-32(d): t = PD/(2SE − 0.2P), P = 2SEt/(D + 0.2t).
    return {{name, k.P * D / (2 * SE - 0.2 * k.P), 2 * SE * k.t / (D + 0.2 * k.t)}};
  }
  const double K = ellipsoidal_head_factor(D, h), ratio = D / (2 * h);
  const std::string name = "Appendix 1-4(c) ellipsoidal, K = " + number_text(K);
  require_head_pressure(k, name);
  if (ratio < 1.0 || ratio > 3.0)
    warnings.push_back("Appendix 1-4(c): " + quantity("D/2h", ratio, "") +
                       " lies outside Table 1-4.1 (1 to 3)");
  // Appendix 1-4(c): t = PDK/(2SE − 0.2P), P = 2SEt/(KD + 0.2t).
  return {{name, k.P * D * K / (2 * SE - 0.2 * k.P), 2 * SE * k.t / (K * D + 0.2 * k.t)}};
}

std::vector<Rule> rules(const TorisphericalHead& head, const Load& k,
                        std::vector<std::string>& warnings) {
  const double D0 = head.inside_diameter, L0 = head.crown_radius, r0 = head.knuckle_radius;
  require_positive(D0, "torispherical head: inside diameter D", "mm");
  require(r0 > 0.0 && r0 < D0 / 2, quantity("torispherical head: knuckle radius r", r0, "mm"),
          "0 < r < D/2 = " + number_text(D0 / 2) + " mm");
  require(L0 >= D0 / 2 && std::isfinite(L0),
          quantity("torispherical head: crown radius L", L0, "mm"),
          ">= D/2 = " + number_text(D0 / 2) + " mm");
  const double L = L0 + k.c, r = r0 + k.c, SE = k.S * k.E;
  // UG-32(j): the crown radius at most the skirt's outside diameter, the knuckle radius at least
  // 6 % of it and at least three times the thickness.
  const double t_nominal = k.t + k.c, outside_diameter = D0 + 2 * t_nominal;
  warn_above(warnings, "UG-32(j)", "crown radius L", L0, "outside diameter D + 2t",
             outside_diameter, "mm");
  warn_above(warnings, "UG-32(j)", "0.06·(D + 2t)", 0.06 * outside_diameter, "knuckle radius r", r0,
             "mm");
  warn_above(warnings, "UG-32(j)", "3t", 3 * t_nominal, "knuckle radius r", r0, "mm");
  warn_above(warnings, "Appendix 1-4(f) applies (not checked)", "0.002·L", 0.002 * L,
             "corroded thickness t − c", k.t, "mm");
  if (close_to(r0 / L0, 0.06)) {
    const std::string name = "UG-32(e) 100 %/6 % torispherical";
    require_head_pressure(k, name);
    // UG-32(e): t = 0.885PL/(SE − 0.1P), P = SEt/(0.885L + 0.1t).
    return {{name, 0.885 * k.P * L / (SE - 0.1 * k.P), SE * k.t / (0.885 * L + 0.1 * k.t)}};
  }
  const double M = torispherical_head_factor(L, r);
  const std::string name = "Appendix 1-4(d) torispherical, M = " + number_text(M);
  require_head_pressure(k, name);
  warn_above(warnings, "Appendix 1-4(d)", "L/r", L / r, "16 2/3 (Table 1-4.2)", 50.0 / 3, "");
  // Appendix 1-4(d): t = PLM/(2SE − 0.2P), P = 2SEt/(LM + 0.2t).
  return {{name, k.P * L * M / (2 * SE - 0.2 * k.P), 2 * SE * k.t / (L * M + 0.2 * k.t)}};
}

std::vector<Rule> rules(const ConicalHead& head, const Load& k,
                        std::vector<std::string>& warnings) {
  const double D0 = head.inside_diameter, a = head.half_angle, r0 = head.knuckle_radius;
  require_positive(D0, "conical head: inside diameter D", "mm");
  require(a > 0.0 && a < std::numbers::pi / 2,
          quantity("conical head: half apex angle α", a * 180 / std::numbers::pi, "°"),
          "0° < α < 90°");
  require(r0 >= 0.0 && r0 < D0 / 2, quantity("conical head: knuckle radius r", r0, "mm"),
          "0 <= r < D/2 = " + number_text(D0 / 2) + " mm");
  const double D = D0 + 2 * k.c, SE = k.S * k.E, ca = std::cos(a);
  const double t_nominal = k.t + k.c, outside_diameter = D0 + 2 * t_nominal;
  warn_above(warnings, r0 > 0.0 ? "UG-32(h)" : "UG-32(g)", "half apex angle α",
             a * 180 / std::numbers::pi, "30° (Appendix 1-5 then applies, not checked)", 30.0, "°");
  // UG-32(g): t = PD/(2 cos α (SE − 0.6P)), P = 2SEt cos α/(D + 1.2t cos α); with a knuckle
  // (UG-32(h)) on the cone's inside diameter where it meets the knuckle, Di = D − 2r(1 − cos α).
  const double r = r0 > 0.0 ? r0 + k.c : 0.0, Di = D - 2 * r * (1 - ca);
  const std::string cone = r0 > 0.0 ? "UG-32(h) toriconical, cone" : "UG-32(g) conical";
  require_pressure_below(k, SE / 0.6, "S·E/0.6", cone);
  std::vector<Rule> out = {
      {cone, k.P * Di / (2 * ca * (SE - 0.6 * k.P)), 2 * SE * k.t * ca / (Di + 1.2 * k.t * ca)}};
  if (r0 > 0.0) {
    warn_above(warnings, "UG-32(h)", "0.06·(D + 2t)", 0.06 * outside_diameter, "knuckle radius r",
               r0, "mm");
    warn_above(warnings, "UG-32(h)", "3t", 3 * t_nominal, "knuckle radius r", r0, "mm");
    // UG-32(h): the knuckle by Appendix 1-4(d) with L = Di/(2 cos α).
    const double L = Di / (2 * ca), M = torispherical_head_factor(L, r);
    const std::string knuckle =
        "UG-32(h) toriconical, knuckle, Appendix 1-4(d) M = " + number_text(M);
    require_head_pressure(k, knuckle);
    out.push_back(
        {knuckle, k.P * L * M / (2 * SE - 0.2 * k.P), 2 * SE * k.t / (L * M + 0.2 * k.t)});
  }
  return out;
}

}  // namespace

CodeCheck check_internal_pressure(const InternalPressureDesign& design) {
  require_positive(design.allowable_stress, "allowable stress S", "MPa");
  require_efficiency(design.joint_efficiency, "joint efficiency E");
  require_positive(design.pressure, "design pressure P", "MPa");
  const double c = design.corrosion_allowance, t = design.nominal_thickness;
  require(c >= 0.0 && std::isfinite(c), quantity("corrosion allowance c", c, "mm"), ">= 0");
  require(t > c && std::isfinite(t), quantity("nominal thickness t", t, "mm"),
          "> corrosion allowance c = " + number_text(c) + " mm");
  const Load load{design.allowable_stress, design.joint_efficiency, design.pressure, t - c, c};

  CodeCheck out;
  const std::vector<Rule> candidates =
      std::visit([&](const auto& part) { return rules(part, load, out.warnings); }, design.part);
  const auto thickest =
      std::max_element(candidates.begin(), candidates.end(),
                       [](const Rule& a, const Rule& b) { return a.thickness < b.thickness; });
  const auto weakest =
      std::min_element(candidates.begin(), candidates.end(),
                       [](const Rule& a, const Rule& b) { return a.pressure < b.pressure; });
  out.required_thickness = thickest->thickness + c;
  out.thickness_formula = thickest->name;
  out.mawp = weakest->pressure;
  out.mawp_formula = weakest->name;
  return out;
}

// Appendix 1-4(c), Table 1-4.1.
double ellipsoidal_head_factor(double inside_diameter, double inside_depth) {
  require_positive(inside_diameter, "ellipsoidal head: inside diameter D", "mm");
  require_positive(inside_depth, "ellipsoidal head: inside depth h", "mm");
  const double ratio = inside_diameter / (2 * inside_depth);
  return (2 + ratio * ratio) / 6;
}

// Appendix 1-4(d), Table 1-4.2.
double torispherical_head_factor(double crown_radius, double knuckle_radius) {
  require_positive(crown_radius, "torispherical head: crown radius L", "mm");
  require_positive(knuckle_radius, "torispherical head: knuckle radius r", "mm");
  return (3 + std::sqrt(crown_radius / knuckle_radius)) / 4;
}

}  // namespace polarform
