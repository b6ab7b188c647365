// One segment of a cam program: a dwell, rise or return over [start, end] (radians) with its
// motion law, and the displacement s(θ) it produces with exact derivatives. SegmentSpec is the
// plain description (what project files store); MotionSegment is the validated, evaluable segment.
// Units: angles in radians, displacement in mm, derivatives in mm/rad^k.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "designers/cam/motion_law.h"
#include "designers/cam/polynomial.h"
#include "designers/cam/scca_law.h"
#include "designers/cam/smoothest_bspline.h"
#include "src/nurbs/bspline.h"

namespace polarform {

enum class SegmentKind { Dwell, Rise, Return };

std::string_view segment_kind_name(SegmentKind kind);  // "dwell", "rise", "return"
// Throws InputError naming the unknown kind and listing the valid names.
SegmentKind parse_segment_kind(std::string_view name);

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
  double lift = 0.0;   // mm: > 0 for a rise or return, 0 for a dwell
  MotionLaw law = MotionLaw::Cycloidal;  // rise and return only
  // Polynomial and B-spline laws: displacement is always met at both ends; derivatives 1..order
  // (velocity, acceleration, jerk) are prescribed at both ends, order in [0, 3]. Order 2 with zero
  // values is Bae 2002, eq. (5.1).
  int constrained_order = 2;
  EndpointDerivatives at_start;
  EndpointDerivatives at_end;
  BSplineLawSettings bspline;  // B-spline law only
  SccaParameters scca;         // SCCA law only

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
  // The exact B-spline form of s on [start, end] when s is piecewise polynomial (dwell,
  // 3-4-5, 4-5-6-7, polynomial, B-spline laws); nullopt for the trigonometric laws.
  std::optional<BSplineFunction> exact() const;

 private:
  struct StandardLaw {
    MotionLaw law;
    double signed_lift;
    std::optional<SccaLaw> scca;  // the SCCA law, integrated once
  };
  SegmentSpec spec_;
  double start_level_ = 0.0;
  double end_level_ = 0.0;
  std::variant<StandardLaw, Polynomial, BSplineFunction> shape_;
};

}  // namespace polarform
