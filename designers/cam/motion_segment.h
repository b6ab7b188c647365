// One segment of a cam program: a dwell, rise, return or rise–return over [start, end] (radians)
// with its motion law, and the displacement s(θ) it produces with exact derivatives. SegmentSpec is
// the plain description (what project files store); MotionSegment is the validated, evaluable
// segment. Units: angles in radians, displacement in mm, derivatives in mm/rad^k.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "designers/cam/constrained_polynomial.h"
#include "designers/cam/motion_law.h"
#include "designers/cam/motion_table.h"
#include "designers/cam/normalised_law.h"
#include "designers/cam/polynomial.h"
#include "designers/cam/scca_law.h"
#include "designers/cam/segment_kind.h"
#include "designers/cam/smoothest_bspline.h"
#include "src/nurbs/bspline.h"

namespace polarform {

// Prescribed derivatives of s at one end of a polynomial or B-spline segment: the actual
// derivatives of s in mm/rad, mm/rad², mm/rad³ (so a return's velocity is negative).
struct EndpointDerivatives {
  double velocity = 0.0;
  double acceleration = 0.0;
  double jerk = 0.0;

  bool operator==(const EndpointDerivatives&) const = default;
};

struct SegmentSpec {
  std::string name;  // shown in messages and diagnostics; "segment N" (1-based position) if empty
  SegmentKind kind = SegmentKind::Dwell;
  double start = 0.0;  // rad
  double end = 0.0;    // rad
  double lift = 0.0;   // mm: > 0 for a rise, return or rise–return, 0 for a dwell
  // Rise, return and rise–return. A rise–return takes the laws with a normalised form
  // (normalised_law.h) and "polynomial": the single polynomial 64x³(1 − x)³ of least degree with
  // s = v = a = 0 at both ends and s = lift at the middle (Norton, Handbook, single-dwell
  // 3-4-5-6 polynomial).
  MotionLaw law = MotionLaw::Cycloidal;
  // Polynomial and B-spline laws: displacement is always met at both ends; derivatives 1..order
  // (velocity, acceleration, jerk) are prescribed at both ends, order in [0, 3]. Order 2 with zero
  // values is Bae 2002, eq. (5.1).
  int constrained_order = 2;
  EndpointDerivatives at_start;
  EndpointDerivatives at_end;
  // Polynomial law on a rise or return only: the degree (0: the least degree the constraints
  // determine, 2·(constrained_order + 1) + interior.size() − 1) and interior constraints in
  // normalised units (constrained_polynomial.h). With either, the law is solved from the end
  // constraints (s, then derivatives 1..constrained_order at both ends) and the interior ones:
  // exactly when they number degree + 1, else the least-jerk-energy polynomial
  // (constrained_polynomial.h).
  int polynomial_degree = 0;
  std::vector<PolynomialConstraint> interior;
  BSplineLawSettings bspline;  // B-spline law only
  SccaParameters scca;         // SCCA law only
  // Constant-velocity law only: the fraction of the segment in each cycloidal blend, in [0, ½]. 0
  // (no blends) only between neighbours that move at the same velocity (CamProgram checks).
  double blend = 0.2;
  MotionTable table;  // table law only

  bool operator==(const SegmentSpec&) const = default;
};

class MotionSegment {
 public:
  // Builds the segment starting at displacement `start_level` (mm); a rise ends at start_level +
  // lift, a return at start_level - lift. Throws InputError naming the segment on a bad spec.
  MotionSegment(SegmentSpec spec, double start_level);

  const SegmentSpec& spec() const { return spec_; }
  const std::string& name() const { return spec_.name; }
  double start() const { return spec_.start; }
  double end() const { return spec_.end; }
  double start_level() const { return start_level_; }
  double end_level() const { return end_level_; }

  // s, s', ..., s^(d) at θ (clamped to [start, end]) into out[0..d], d <= 4; mm/rad^k.
  void derivatives(double theta, int d, double* out) const;
  // The exact B-spline form of s on [start, end] when s is polynomial or a B-spline (dwell,
  // cubic, 3-4-5, 4-5-6-7 on a rise or return; polynomial, B-spline and table laws); nullopt for
  // the others.
  std::optional<BSplineFunction> exact() const;
  // Angles in (start, end) where the law's pieces join (where the jerk may jump), increasing.
  std::vector<double> joins() const;
  // Polynomial laws (not a rise–return's): the degree, and whether fewer constraints than
  // coefficients left it to the least jerk energy.
  int polynomial_degree() const;
  bool least_jerk_energy() const { return least_jerk_energy_; }
  // s as a polynomial in t = (θ − start)/β (dwells and polynomial laws), else null.
  const Polynomial* polynomial() const { return std::get_if<Polynomial>(&shape_); }

 private:
  BSplineFunction table_shape() const;
  Polynomial solved_polynomial(double signed_lift);

  struct ScaledLaw {
    NormalisedLaw law;  // SCCA integrated once
    double signed_lift;
  };
  SegmentSpec spec_;
  double start_level_ = 0.0;
  double end_level_ = 0.0;
  bool least_jerk_energy_ = false;
  std::variant<Polynomial, ScaledLaw, BSplineFunction> shape_;
};

}  // namespace polarform
