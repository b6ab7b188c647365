// The SCCA family of normalised motion laws (sine–constant–cosine acceleration; Norton, Cam Design
// and Manufacturing Handbook, 2nd ed., §3.9): over x in [0, 1] the acceleration rises as a quarter
// sine over b/2, stays constant up to (1 − d)/2, turns through a half cosine to its negative over
// d, stays constant and returns to 0 as a quarter sine over the last b/2 — b + c + d = 1. Special
// cases: constant acceleration (0, 1, 0), modified trapezoid (0.25, 0.5, 0.25), simple harmonic
// (0, 0, 1), modified sine (0.25, 0, 0.75), cycloidal (0.5, 0, 0.5).
#pragma once

#include <vector>

namespace polarform {

struct SccaParameters {
  double b = 0.25;  // fraction in sine ramps
  double c = 0.5;   // fraction at constant acceleration
  double d = 0.25;  // fraction in the cosine turn

  bool operator==(const SccaParameters&) const = default;
};

// The law of given fractions, its zones integrated once so that evaluating it is a zone lookup and
// a closed form.
class SccaLaw {
 public:
  // Throws InputError unless b, c, d >= 0 are finite and add up to 1 (to 1e-9).
  explicit SccaLaw(const SccaParameters& parameters);

  const SccaParameters& parameters() const { return parameters_; }
  // S(x), S'(x), …, S^(k)(x) (k <= 4) with S(0) = 0, S(1) = 1; x clamped to [0, 1].
  void derivatives(double x, int k, double* out) const;
  // The x in (0, 1) where the zones join (where the jerk may jump).
  std::vector<double> joins() const;

 private:
  // One zone [x0, x1] of the unscaled acceleration a = A sin(ω t + φ), t = x − x0 (the constant A
  // when ω = 0), entered with displacement s0 and velocity v0.
  struct Zone {
    double x0, x1, A, w, phi, s0, v0;
  };
  SccaParameters parameters_;
  std::vector<Zone> zones_;
  double scale_ = 1.0;  // 1 / the unscaled S(1)
};

}  // namespace polarform
