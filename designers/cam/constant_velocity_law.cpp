#include "designers/cam/constant_velocity_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

ConstantVelocityLaw::ConstantVelocityLaw(double blend) : blend_(blend) {
  if (!(blend >= 0.0 && blend <= 0.5))
    throw InputError("constant-velocity law: blend = " + number_text(blend) +
                     ", expected a fraction of the segment at each end in [0, 0.5]");
}

double ConstantVelocityLaw::peak_acceleration() const {
  return blend_ > 0 ? kPi / (2 * blend_ * (1 - blend_)) : HUGE_VAL;
}

// The law on [0, ½], reflected about (½, ½) like every antisymmetric law: the blend is the first
// half of a cycloid scaled to reach V at x = f, then S = V(x − f/2).
void ConstantVelocityLaw::derivatives(double x, int k, double* out) const {
  if (k < 0 || k > 4)
    throw InputError("constant-velocity law: derivative order " + std::to_string(k) +
                     " outside [0, 4]");
  x = std::clamp(x, 0.0, 1.0);
  const bool reflect = x > 0.5;
  const double t = reflect ? 1.0 - x : x, f = blend_, v = velocity();
  double o[5] = {v * (t - f / 2), v, 0, 0, 0};
  if (f > 0 &&
      t <= f) {  // a = A sin(w t), w = π/f: v = A/w (1 − cos w t), s = A/w (t − sin(w t)/w)
    const double w = kPi / f, a = peak_acceleration(), sn = std::sin(w * t), cs = std::cos(w * t);
    o[0] = a / w * (t - sn / w);
    o[1] = a / w * (1 - cs);
    o[2] = a * sn;
    o[3] = a * w * cs;
    o[4] = -a * w * w * sn;
  }
  if (reflect) {  // S(x) = 1 − S(1 − x), S^(k)(x) = (−1)^(k+1) S^(k)(1 − x)
    o[0] = 1.0 - o[0];
    o[2] = -o[2];
    o[4] = -o[4];
  }
  std::copy(o, o + k + 1, out);
}

std::vector<double> ConstantVelocityLaw::joins() const {
  if (blend_ == 0.0 || blend_ == 0.5) return {};
  return {blend_, 1.0 - blend_};
}

}  // namespace polarform
