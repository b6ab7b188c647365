#include "tests/support/designers/example_cams.h"

#include <stdexcept>

#include "src/units.h"

namespace polarform::test {

namespace {

// The segments of a program from 0° to 360°: each starts where the previous one ends, and a
// return without a lift falls back to the level reached so far (as project files read).
class Segments {
 public:
  Segments& dwell(double to_deg) {
    return add(SegmentKind::Dwell, MotionLaw::Cycloidal, 0, to_deg);
  }
  Segments& rise(MotionLaw law, double lift, double to_deg) {
    return add(SegmentKind::Rise, law, lift, to_deg);
  }
  Segments& ret(MotionLaw law, double to_deg) {
    return add(SegmentKind::Return, law, level_, to_deg);
  }
  // Polynomial laws: the last segment's prescribed endpoint derivatives, all zero, up to `order`.
  Segments& zero_endpoint_derivatives(int order) {
    specs_.back().constrained_order = order;
    return *this;
  }
  std::vector<SegmentSpec> specs() const { return specs_; }

 private:
  Segments& add(SegmentKind kind, MotionLaw law, double lift, double to_deg) {
    SegmentSpec s;
    s.kind = kind;
    s.start = specs_.empty() ? 0.0 : specs_.back().end;
    s.end = to_deg * kRadiansPerDegree;
    if (kind != SegmentKind::Dwell) s.law = law, s.lift = lift;
    level_ += kind == SegmentKind::Rise ? lift : kind == SegmentKind::Return ? -lift : 0.0;
    specs_.push_back(s);
    return *this;
  }
  std::vector<SegmentSpec> specs_;
  double level_ = 0.0;
};

CamDesign plate(FollowerKind follower, double base_radius, double roller_radius, double offset,
                Rotation rotation, double rpm, const Segments& segments) {
  CamDesign d;
  d.type = CamType::Plate;
  d.follower = {follower, offset, roller_radius};
  d.base_radius = base_radius;
  d.rotation = rotation;
  d.rpm = rpm;
  d.segments = segments.specs();
  return d;
}

}  // namespace

const std::vector<std::string>& example_cam_names() {
  static const std::vector<std::string> names = {"roller", "flat_faced", "offset_roller",
                                                 "polynomial", "cylindrical"};
  return names;
}

CamDesign example_cam_design(const std::string& name) {
  constexpr Rotation ccw = Rotation::CounterClockwise, cw = Rotation::Clockwise;
  constexpr FollowerKind roller = FollowerKind::Roller;
  if (name == "roller")
    return plate(roller, 40, 10, 0, ccw, 300,
                 Segments()
                     .dwell(90)
                     .rise(MotionLaw::Cycloidal, 20, 180)
                     .dwell(240)
                     .ret(MotionLaw::Polynomial4567, 360));
  if (name == "flat_faced")
    return plate(FollowerKind::FlatFaced, 35, 0, 0, cw, 600,
                 Segments()
                     .rise(MotionLaw::Polynomial345, 12, 100)
                     .dwell(170)
                     .ret(MotionLaw::ModifiedSine, 280)
                     .dwell(360));
  if (name == "offset_roller")
    return plate(roller, 45, 12, 8, ccw, 400,
                 Segments()
                     .dwell(60)
                     .rise(MotionLaw::ModifiedTrapezoid, 25, 170)
                     .dwell(200)
                     .ret(MotionLaw::SimpleHarmonic, 330)
                     .dwell(360));
  if (name == "polynomial")
    return plate(roller, 50, 10, 0, ccw, 250,
                 Segments()
                     .dwell(30)
                     .rise(MotionLaw::Polynomial, 18, 150)
                     .zero_endpoint_derivatives(3)
                     .dwell(200)
                     .ret(MotionLaw::Polynomial, 330)
                     .zero_endpoint_derivatives(2)
                     .dwell(360));
  if (name == "cylindrical") {
    CamDesign d;
    d.type = CamType::Cylindrical;
    d.follower = {roller, 0, 8};
    d.base_radius = 0;
    d.cylinder_radius = 60;
    d.groove_depth = 16;
    d.rotation = ccw;
    d.rpm = 200;
    d.segments = Segments()
                     .dwell(45)
                     .rise(MotionLaw::Cycloidal, 30, 180)
                     .dwell(225)
                     .ret(MotionLaw::Cycloidal, 360)
                     .specs();
    return d;
  }
  throw std::invalid_argument("no example cam '" + name + "'");
}

}  // namespace polarform::test
