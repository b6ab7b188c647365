#include "designers/cam/scca_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;

// One zone [x0, x1] of the unscaled acceleration: a = A sin(ω t + φ), t = x − x0 (ω > 0), or the
// constant A (ω = 0).
struct Zone {
  double x0, x1;
  double A, w, phi;
};

std::vector<Zone> zones(const SccaParameters& p) {
  const double h = p.b / 2, x2 = (1 - p.d) / 2, x3 = (1 + p.d) / 2, x4 = 1 - h;
  std::vector<Zone> all = {{0, h, 1, kPi / p.b, 0},           // quarter sine up
                           {h, x2, 1, 0, 0},                  // constant
                           {x2, x3, 1, kPi / p.d, kPi / 2},   // half cosine through 0
                           {x3, x4, -1, 0, 0},                // constant, negative
                           {x4, 1, 1, kPi / p.b, -kPi / 2}};  // quarter sine back to 0
  std::erase_if(all, [](const Zone& z) { return !(z.x1 > z.x0); });
  return all;
}

// s, s', s'', s''', s'''' at t in the zone from s0, v0 at its start (closed-form integrals).
void zone_values(const Zone& z, double s0, double v0, double t, double* o) {
  if (z.w == 0.0) {
    o[0] = s0 + v0 * t + z.A * t * t / 2;
    o[1] = v0 + z.A * t;
    o[2] = z.A;
    o[3] = o[4] = 0.0;
    return;
  }
  const double arg = z.w * t + z.phi, sn = std::sin(arg), cs = std::cos(arg);
  const double c0 = std::cos(z.phi), s0n = std::sin(z.phi);
  o[0] = s0 + v0 * t + z.A / z.w * t * c0 - z.A / (z.w * z.w) * (sn - s0n);
  o[1] = v0 + z.A / z.w * (c0 - cs);
  o[2] = z.A * sn;
  o[3] = z.A * z.w * cs;
  o[4] = -z.A * z.w * z.w * sn;
}

}  // namespace

void check_scca(const SccaParameters& p) {
  for (const auto& [name, v] : {std::pair{"b", p.b}, std::pair{"c", p.c}, std::pair{"d", p.d}})
    if (!(v >= 0.0 && std::isfinite(v)))
      throw InputError(std::string("SCCA law: ") + name + " = " + number_text(v) +
                       ", expected a fraction >= 0");
  if (std::abs(p.b + p.c + p.d - 1) > 1e-9)
    throw InputError("SCCA law: b + c + d = " + number_text(p.b + p.c + p.d) +
                     ", expected 1 (b sine ramps, c constant, d cosine turn)");
}

// Norton §3.9: the zones' closed-form integrals carried zone to zone, then S scaled to S(1) = 1.
void scca_law(const SccaParameters& p, double x, int k, double* out) {
  check_scca(p);
  if (k < 0 || k > 4)
    throw InputError("SCCA law: derivative order " + std::to_string(k) + " outside [0, 4]");
  x = std::clamp(x, 0.0, 1.0);
  const std::vector<Zone> all = zones(p);
  double s = 0.0, v = 0.0, at[5] = {0, 0, 0, 0, 0}, end[5];
  bool found = false;
  for (const Zone& z : all) {
    if (!found && x <= z.x1) {
      zone_values(z, s, v, x - z.x0, at);
      found = true;
    }
    zone_values(z, s, v, z.x1 - z.x0, end);
    s = end[0];
    v = end[1];
  }
  const double scale = 1.0 / s;  // the unscaled S(1)
  for (int i = 0; i <= k; ++i) out[i] = at[i] * scale;
}

std::vector<double> scca_joins(const SccaParameters& p) {
  check_scca(p);
  std::vector<double> joins;
  for (const Zone& z : zones(p))
    if (z.x0 > 0.0) joins.push_back(z.x0);
  return joins;
}

}  // namespace polarform
