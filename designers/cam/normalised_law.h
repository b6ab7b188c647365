// The normalised shape of a rise, return or rise–return whose law has a closed form (a standard
// law, SCCA, constant velocity): S(x) over x in [0, 1] is the fraction of the lift travelled, its
// derivatives with respect to x. A return runs the rise's mirror image 1 − S(1 − x) (the same law
// unless it is not antisymmetric: the double harmonic, Rothbart, Cams (1956), whose return is its
// rise played backwards); a rise–return rises with the law over the first half and returns with
// its mirror image over the second, so it is C² at the top for every law.
#pragma once

#include <optional>
#include <vector>

#include "designers/cam/constant_velocity_law.h"
#include "designers/cam/motion_law.h"
#include "designers/cam/scca_law.h"
#include "designers/cam/segment_kind.h"

namespace polarform {

// Whether a law has a normalised closed form (standard, SCCA, constant velocity).
bool has_normalised_form(MotionLaw law);

class NormalisedLaw {
 public:
  // Throws InputError for a dwell, a law without a normalised form or bad SCCA / blend parameters.
  NormalisedLaw(SegmentKind kind, MotionLaw law, const SccaParameters& scca, double blend);

  // S(x), S'(x), …, S^(d)(x) (d <= 4); x clamped to [0, 1].
  void derivatives(double x, int d, double* out) const;
  // The x in (0, 1) where the pieces join (where the jerk may jump), increasing.
  std::vector<double> joins() const;

 private:
  void rise(double x, int d, double* out) const;  // the law as a rise
  std::vector<double> rise_joins() const;

  SegmentKind kind_;
  MotionLaw law_;
  std::optional<SccaLaw> scca_;
  std::optional<ConstantVelocityLaw> constant_velocity_;
};

}  // namespace polarform
