#include "designers/cam/normalised_law.h"

#include <algorithm>
#include <string>

#include "src/error.h"

namespace polarform {

namespace {

// S(x) ↦ 1 − S(1 − x) for derivatives evaluated at 1 − x: S^(k) picks up (−1)^(k+1).
void mirror(int d, double* o) {
  o[0] = 1.0 - o[0];
  for (int k = 2; k <= d; k += 2) o[k] = -o[k];
}

}  // namespace

bool has_normalised_form(MotionLaw law) {
  return is_standard_law(law) || law == MotionLaw::Scca || law == MotionLaw::ConstantVelocity;
}

NormalisedLaw::NormalisedLaw(SegmentKind kind, MotionLaw law, const SccaParameters& scca,
                             double blend)
    : kind_(kind), law_(law) {
  if (kind == SegmentKind::Dwell) throw InputError("a dwell has no motion law");
  if (!has_normalised_form(law))
    throw InputError("motion law '" + std::string(motion_law_name(law)) +
                     "' has no normalised closed form (it is synthesised or tabulated)");
  if (law == MotionLaw::Scca) scca_.emplace(scca);
  if (law == MotionLaw::ConstantVelocity) constant_velocity_.emplace(blend);
}

void NormalisedLaw::rise(double x, int d, double* out) const {
  if (scca_)
    scca_->derivatives(x, d, out);
  else if (constant_velocity_)
    constant_velocity_->derivatives(x, d, out);
  else
    standard_law(law_, x, d, out);
}

void NormalisedLaw::derivatives(double x, int d, double* out) const {
  if (d < 0 || d > 4)
    throw InputError("motion law: derivative order " + std::to_string(d) + " outside [0, 4]");
  x = std::clamp(x, 0.0, 1.0);
  if (kind_ == SegmentKind::Return && !is_antisymmetric_law(law_)) {
    rise(1.0 - x, d, out);
    mirror(d, out);
    return;
  }
  if (kind_ != SegmentKind::RiseReturn) return rise(x, d, out);
  // Rise over [0, ½] as S(2x), return over [½, 1] as S(2 − 2x): the k-th derivative scales by 2^k,
  // and on the way down the odd ones change sign.
  const bool down = x > 0.5;
  rise(down ? 2.0 - 2.0 * x : 2.0 * x, d, out);
  double scale = 1.0;
  for (int k = 1; k <= d; ++k) out[k] *= (scale *= down ? -2.0 : 2.0);
}

std::vector<double> NormalisedLaw::rise_joins() const {
  if (scca_) return scca_->joins();
  if (constant_velocity_) return constant_velocity_->joins();
  return law_joins(law_);
}

std::vector<double> NormalisedLaw::joins() const {
  std::vector<double> joins = rise_joins();
  if (kind_ == SegmentKind::Return && !is_antisymmetric_law(law_)) {
    for (double& x : joins) x = 1.0 - x;
  } else if (kind_ == SegmentKind::RiseReturn) {
    std::vector<double> both = {0.5};
    for (double x : joins) both.insert(both.end(), {x / 2, 1.0 - x / 2});
    joins = std::move(both);
  }
  std::sort(joins.begin(), joins.end());
  return joins;
}

}  // namespace polarform
