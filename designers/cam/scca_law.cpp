#include "designers/cam/scca_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;

void check(const SccaParameters& p) {
  for (const auto& [name, v] : {std::pair{"b", p.b}, std::pair{"c", p.c}, std::pair{"d", p.d}})
    if (!(v >= 0.0 && std::isfinite(v)))
      throw InputError(std::string("SCCA law: ") + name + " = " + number_text(v) +
                       ", expected a fraction >= 0");
  if (std::abs(p.b + p.c + p.d - 1) > 1e-9)
    throw InputError("SCCA law: b + c + d = " + number_text(p.b + p.c + p.d) +
                     ", expected 1 (b sine ramps, c constant, d cosine turn)");
}

// s .. s'''' at t into a zone of a = A sin(ω t + φ) (or the constant A) entered with s0, v0: the
// closed-form integrals.
void zone_values(double A, double w, double phi, double s0, double v0, double t, double* o) {
  if (w == 0.0) {
    o[0] = s0 + v0 * t + A * t * t / 2;
    o[1] = v0 + A * t;
    o[2] = A;
    o[3] = o[4] = 0.0;
    return;
  }
  const double arg = w * t + phi, sn = std::sin(arg), cs = std::cos(arg);
  const double c0 = std::cos(phi), s0n = std::sin(phi);
  o[0] = s0 + v0 * t + A / w * t * c0 - A / (w * w) * (sn - s0n);
  o[1] = v0 + A / w * (c0 - cs);
  o[2] = A * sn;
  o[3] = A * w * cs;
  o[4] = -A * w * w * sn;
}

}  // namespace

// Norton §3.9: quarter sine up over b/2, constant to (1 − d)/2, half cosine through 0 over d,
// constant negative, quarter sine back to 0; each zone's start values carried from the last.
SccaLaw::SccaLaw(const SccaParameters& p) : parameters_(p) {
  check(p);
  const double h = p.b / 2, x2 = (1 - p.d) / 2, x3 = (1 + p.d) / 2, x4 = 1 - h;
  const Zone all[] = {{0, h, 1, kPi / p.b, 0, 0, 0},
                      {h, x2, 1, 0, 0, 0, 0},
                      {x2, x3, 1, kPi / p.d, kPi / 2, 0, 0},
                      {x3, x4, -1, 0, 0, 0, 0},
                      {x4, 1, 1, kPi / p.b, -kPi / 2, 0, 0}};
  double s = 0.0, v = 0.0, end[5];
  for (Zone z : all) {
    if (!(z.x1 > z.x0)) continue;
    z.s0 = s;
    z.v0 = v;
    zone_values(z.A, z.w, z.phi, s, v, z.x1 - z.x0, end);
    s = end[0];
    v = end[1];
    zones_.push_back(z);
  }
  scale_ = 1.0 / s;
}

void SccaLaw::derivatives(double x, int k, double* out) const {
  if (k < 0 || k > 4)
    throw InputError("SCCA law: derivative order " + std::to_string(k) + " outside [0, 4]");
  x = std::clamp(x, 0.0, 1.0);
  const auto z = std::find_if(zones_.begin(), zones_.end() - 1,
                              [x](const Zone& zone) { return x <= zone.x1; });
  double at[5];
  zone_values(z->A, z->w, z->phi, z->s0, z->v0, x - z->x0, at);
  for (int i = 0; i <= k; ++i) out[i] = at[i] * scale_;
}

// A zone thinner than kThinZone (a fraction meant as 0, e.g. fitted) adds no join of its own: the
// law's value there differs from its neighbours' by less than the zone's width.
std::vector<double> SccaLaw::joins() const {
  constexpr double kThinZone = 1e-9;
  std::vector<double> joins;
  for (const Zone& z : zones_)
    if (z.x0 > kThinZone && z.x0 < 1 - kThinZone &&
        (joins.empty() || z.x0 - joins.back() > kThinZone))
      joins.push_back(z.x0);
  return joins;
}

}  // namespace polarform
