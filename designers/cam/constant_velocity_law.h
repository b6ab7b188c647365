// Constant velocity with cycloidal blends (the cycloidal–constant-velocity law; Rothbart, Cams
// (1956), modified constant velocity; Norton, Handbook, constant velocity needs blends): over the
// first and the last fraction f of the segment the acceleration is a half sine pulse ±A sin(πx/f)
// — the first half of a cycloidal rise, so acceleration is 0 at the dwell and at the constant-
// velocity part, continuous throughout — and in between the velocity is constant. f = ½ is the
// cycloidal law; f = 0 is pure constant velocity S = x (a velocity step at the ends).
#pragma once

#include <vector>

namespace polarform {

class ConstantVelocityLaw {
 public:
  // Throws InputError unless 0 <= blend <= ½ (the blend fraction at each end).
  explicit ConstantVelocityLaw(double blend);

  double blend() const { return blend_; }
  // The constant velocity V = 1/(1 − f) and the blends' peak acceleration A = π/(2f(1 − f)):
  // from V·f/2 travelled in each blend and V(1 − 2f) in between adding up to 1.
  double velocity() const { return 1.0 / (1.0 - blend_); }
  double peak_acceleration() const;
  // S(x), S'(x), …, S^(k)(x) (k <= 4), S(0) = 0, S(1) = 1; x clamped to [0, 1].
  void derivatives(double x, int k, double* out) const;
  // f and 1 − f where the blends meet the constant velocity (none for f = 0 or ½).
  std::vector<double> joins() const;

 private:
  double blend_;
};

}  // namespace polarform
