// CamProgram: the follower-displacement program s(θ) of a cam over one revolution, built from
// dwell / rise / return / rise–return segments that cover [0, 2π) without gaps or overlaps (Bae
// 2002, §5.1, Figure 5.1). s is measured from the lowest segment-boundary level (the base circle);
// it comes with exact θ-derivatives, time derivatives at a given speed, and its exact piecewise
// B-spline form when every segment is polynomial. Immutable and cheap to copy (segments are
// shared).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "designers/cam/motion_segment.h"
#include "src/nurbs/bspline.h"

namespace polarform {

// θ reduced to [0, 2π).
double wrap_angle(double theta);

// The fastest cam speed accepted, rev/min: above any machine cam, and far below the speeds at
// which the jerk s‴·ω³ overflows (input limit).
constexpr double kMaxRpm = 1e5;

// Follower motion at constant cam speed ω = 2π·rpm/60: mm, mm/s, mm/s², mm/s³.
struct Kinematics {
  double displacement = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
  double jerk = 0.0;
};

class CamProgram {
 public:
  // Sorts the segments by start angle, names unnamed ones "segment N" (N = 1-based position in
  // the given list) and validates: each segment (see MotionSegment), the first starts at 0 and the
  // last ends at 2π, consecutive segments meet (within 1e-9 rad; the angles are then snapped
  // together), the rises and returns cancel over the revolution, and a constant-velocity segment
  // without blends meets neighbours at its velocity. Throws InputError naming the segments and
  // angles involved.
  explicit CamProgram(std::vector<SegmentSpec> segments);

  const std::vector<MotionSegment>& segments() const { return data_->segments; }
  // Segment holding θ (wrapped into [0, 2π)); at a boundary, the segment that starts there.
  int segment_index(double theta) const;

  // s, s', ..., s^(d) at θ (any real angle, periodic) into out[0..d], d <= 4; mm/rad^k.
  void derivatives(double theta, int d, double* out) const;
  double operator()(double theta) const;
  // Angles in (0, 2π) where s may lose smoothness: the segment boundaries and the joins inside
  // piecewise laws (law_joins), increasing.
  std::vector<double> smoothness_breaks() const;
  // Largest follower level: the segment boundaries and the tops of rise-returns.
  double stroke() const { return data_->stroke; }
  // Time derivatives at θ for a cam turning at rpm revolutions per minute (rpm > 0).
  Kinematics kinematics(double theta, double rpm) const;

  // The exact B-spline form of s on [0, 2π] when every segment is polynomial: each segment's
  // Bezier/B-spline pieces raised to the highest segment degree p and joined with knots of
  // multiplicity p at the segment boundaries (C0 joins in the knot vector; the actual continuity
  // is whatever the segments have). nullopt if any segment uses a trigonometric law.
  std::optional<BSplineFunction> exact() const;

 private:
  struct Data {
    std::vector<MotionSegment> segments;
    std::vector<double> starts;  // segment start angles, for the segment search
    double stroke = 0.0;
  };
  std::shared_ptr<const Data> data_;
};

}  // namespace polarform
