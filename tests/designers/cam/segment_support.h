// Building segment specs in cam tests: a segment by kind, angles in degrees, lift and law.
#pragma once

#include "designers/cam/motion_segment.h"
#include "src/units.h"

namespace polarform::test {

inline SegmentSpec segment(SegmentKind kind, double from_deg, double to_deg, double lift,
                           MotionLaw law) {
  SegmentSpec s;
  s.kind = kind;
  s.start = from_deg * kRadiansPerDegree;
  s.end = to_deg * kRadiansPerDegree;
  s.lift = lift;
  s.law = law;
  return s;
}

}  // namespace polarform::test
