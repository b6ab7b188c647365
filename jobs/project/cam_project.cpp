#include "jobs/project/cam_project.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "export/atomic_file.h"
#include "export/xml_escape.h"
#include "jobs/project/compaction_attribute.h"
#include "jobs/project/motion_table_csv.h"
#include "jobs/project/xml_reader.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

using tinyxml2::XMLElement;

std::string number(double x) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, result.ptr);
}

// An angle in degrees for messages, to 12 significant digits: 240° reads "240", not the
// 239.99999999999997 that radians → degrees gives back.
std::string degrees_text(double radians) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, radians * kDegreesPerRadian,
                                    std::chars_format::general, 12);
  return std::string(buf, result.ptr) + "°";
}

// The degree value whose conversion d·π/180 gives back exactly `radians` (searched among the
// neighbours of the rounded quotient), so that save → load is exact.
double degrees_for(double radians) {
  double d = radians * kDegreesPerRadian;
  for (int k = 0; k < 8 && d * kRadiansPerDegree != radians; ++k)
    d = std::nextafter(d, d * kRadiansPerDegree < radians ? HUGE_VAL : -HUGE_VAL);
  return d;
}

// The constraint children of a polynomial or B-spline segment; order = highest derivative given.
void read_constraints(const XmlElementReader& seg, SegmentSpec& spec, const std::string& file,
                      std::vector<UnknownName>& unknown) {
  const XMLElement* start = seg.child("start");
  const XMLElement* end = seg.child("end");
  if (!start && !end) return;  // Bae 2002, eq. (5.1): v = a = 0 at both ends
  int order = 0;
  auto read_end = [&](const XMLElement* e, EndpointDerivatives& d) {
    if (!e) return;
    const XmlElementReader r(e, file);
    if (r.has("v")) d.velocity = r.number("v"), order = std::max(order, 1);
    if (r.has("a")) d.acceleration = r.number("a"), order = std::max(order, 2);
    if (r.has("j")) d.jerk = r.number("j"), order = std::max(order, 3);
    r.collect_unknown_names(unknown);
  };
  read_end(start, spec.at_start);
  read_end(end, spec.at_end);
  spec.constrained_order = order;
}

// A polynomial law's degree="N" and <constraint x="" derivative="" value=""/> children
// (constrained_polynomial.h): x in (0, 1), S^(derivative)(x) = value in normalised units.
void read_polynomial(const XmlElementReader& seg, SegmentSpec& spec, const std::string& file,
                     std::vector<UnknownName>& unknown) {
  if (seg.has("degree")) {
    spec.polynomial_degree = seg.integer("degree", 0);
    if (spec.polynomial_degree < 1 || spec.polynomial_degree > kMaxConstrainedPolynomialDegree)
      seg.fail("degree", "an integer in [1, " + std::to_string(kMaxConstrainedPolynomialDegree) +
                             "], or no degree for the least one the constraints determine");
  }
  for (const XMLElement* e : seg.children("constraint")) {
    const XmlElementReader r(e, file);
    PolynomialConstraint c;
    c.x = r.number("x");
    if (!(c.x > 0 && c.x < 1))
      r.fail("x", "a normalised position strictly inside (0, 1) (the ends are <start> and <end>)");
    c.derivative = r.integer("derivative", 0);
    if (c.derivative < 0 || c.derivative > kMaxConstraintDerivative)
      r.fail("derivative", "an integer in [0, " + std::to_string(kMaxConstraintDerivative) +
                               "] (0: S, 1: S', 2: S'', ...)");
    c.value = r.number("value");
    r.collect_unknown_names(unknown);
    spec.interior.push_back(c);
  }
}

SegmentSpec read_segment(const XmlElementReader& r, double from, double level,
                         const std::string& file, std::vector<UnknownName>& unknown) {
  SegmentSpec s;
  s.kind = parse_segment_kind(r.choice("kind", {"dwell", "rise", "return", "rise-return"}));
  s.name = r.text("name", "");
  s.start = r.number("from", from * kDegreesPerRadian) * kRadiansPerDegree;
  s.end = r.number("to") * kRadiansPerDegree;
  if (!(s.end > s.start))
    r.fail("to", "an angle after the segment start " + degrees_text(s.start));
  if (s.kind == SegmentKind::Dwell) return s;
  try {
    s.law = parse_motion_law(r.text("law", "cycloidal"));
  } catch (const InputError& e) {
    r.fail("law", std::string("a motion law (") + e.what() + ")");
  }
  if (s.kind == SegmentKind::Return)
    s.lift = r.positive("lift", level);
  else
    s.lift = r.positive("lift");
  if (!(s.lift > 0)) r.fail("lift", "a lift > 0 mm (the follower is already at the base circle)");
  if ((s.law == MotionLaw::Polynomial && s.kind != SegmentKind::RiseReturn) ||
      s.law == MotionLaw::BSpline)
    read_constraints(r, s, file, unknown);
  if (s.law == MotionLaw::Polynomial && s.kind != SegmentKind::RiseReturn)
    read_polynomial(r, s, file, unknown);
  if (s.law ==
      MotionLaw::ConstantVelocity) {  // the blend fraction at each end (constant_velocity_law.h)
    s.blend = r.positive("blend", s.blend, true);
    if (!(s.blend <= 0.5)) r.fail("blend", "a fraction of the segment at each end in [0, 0.5]");
  }
  if (s.law == MotionLaw::Table) {  // a table file relative to the project (motion_table_csv.h)
    if (s.kind == SegmentKind::RiseReturn) r.fail("law", "a rise or return for a motion table");
    const TableEnds ends =
        r.choice("ends", {"rest", "free"}, "rest") == "rest" ? TableEnds::Rest : TableEnds::Free;
    const std::string name = r.text("file", "");
    if (name.empty()) r.fail("file", "the motion table's file name (CSV, relative to the project)");
    s.table =
        read_motion_table(file, name, {s.start, s.end, s.lift, s.kind == SegmentKind::Rise}, ends);
  }
  if (s.law == MotionLaw::Scca) {  // the fractions b, c, d (scca_law.h)
    s.scca.b = r.positive("b", s.scca.b, true);
    s.scca.c = r.positive("c", s.scca.c, true);
    s.scca.d = r.positive("d", s.scca.d, true);
    if (std::abs(s.scca.b + s.scca.c + s.scca.d - 1) > 1e-9)
      r.fail("d", "fractions with b + c + d = 1, got b + c + d = " +
                      number(s.scca.b + s.scca.c + s.scca.d));
  }
  if (s.law == MotionLaw::BSpline) {
    s.bspline.degree = r.integer("degree", s.bspline.degree);
    s.bspline.control_values = r.integer("control-values", s.bspline.control_values);
    if (s.bspline.control_values < 1 || s.bspline.control_values > kMaxBSplineControlValues)
      r.fail("control-values",
             "an integer in [1, " + std::to_string(kMaxBSplineControlValues) + "]");
    s.bspline.minimised_derivative = r.integer("minimise", s.bspline.minimised_derivative);
  }
  return s;
}

// <dynamics mass="kg" spring-rate="N/mm" preload="N" damping="N·s/mm" contact-width="mm"
//           youngs-modulus="MPa" poisson-ratio="0.3"/>; per-length quantities in the file's unit.
// An oscillating follower's arm instead: inertia="kg·m²" torsion-rate="N·m/rad"
// preload-torque="N·m" torsion-damping="N·m·s/rad" (no lengths).
FollowerLoad read_dynamics(const XmlElementReader& r, double unit, bool arm) {
  FollowerLoad l;
  l.arm = arm;
  if (arm) {
    l.inertia = r.positive("inertia");
    l.torsion_rate = r.positive("torsion-rate", 0.0, true);
    l.preload_torque = r.positive("preload-torque", 0.0, true);
    l.torsion_damping = r.positive("torsion-damping", 0.0, true);
  } else {
    l.mass = r.positive("mass");
    l.spring_rate = r.positive("spring-rate", 0.0, true) / unit;
    l.preload = r.positive("preload", 0.0, true);
    l.damping = r.positive("damping", 0.0, true) / unit;
  }
  l.contact_width = r.positive("contact-width", 0.0, true) * unit;
  l.youngs_modulus = r.positive("youngs-modulus", l.youngs_modulus);
  l.poisson_ratio = r.positive("poisson-ratio", l.poisson_ratio, true);
  if (!(l.poisson_ratio < 0.5)) r.fail("poisson-ratio", "a Poisson ratio in [0, 0.5)");
  return l;
}

// An oscillating follower's arm (plate_cam.h): pivot-distance, arm-length (roller) or face-offset
// (flat face), pivot-side.
void read_arm(const XmlElementReader& r, Follower& f) {
  f.pivot_distance = r.positive("pivot-distance");
  if (f.kind == FollowerKind::OscillatingRoller)
    f.arm_length = r.positive("arm-length");
  else
    f.face_offset = r.number("face-offset", 0.0);
  f.pivot_side = r.choice("pivot-side", {"right", "left"}, "right") == "right" ? 1 : -1;
}

// <conjugate roller-distance="mm"/> (translating roller) or <conjugate arm-angle="deg"
// arm-length="mm"/> (oscillating roller), both with an optional roller-radius="mm" (default: the
// first roller's): the second cam's roller (conjugate_cam.h).
ConjugateFollower read_conjugate(const XmlElementReader& r, const CamDesign& d,
                                 std::vector<UnknownName>& unknown) {
  ConjugateFollower c;
  if (d.follower.kind == FollowerKind::Roller) {
    c.roller_distance = r.positive("roller-distance");
  } else if (d.follower.kind == FollowerKind::OscillatingRoller) {
    c.arm_angle = r.number("arm-angle") * kRadiansPerDegree;
    if (!(std::abs(c.arm_angle) < std::numbers::pi))
      r.fail("arm-angle", "an angle in (−180, 180) degrees from the first arm to the second");
    c.arm_length = r.positive("arm-length");
  } else {
    throw InputError(r.where() +
                     ": <conjugate> needs a roller or oscillating-roller follower, not "
                     "a " +
                     std::string(follower_kind_name(d.follower.kind)) + " follower");
  }
  c.roller_radius = r.positive("roller-radius", 0.0, true);  // 0: the first roller's
  r.collect_unknown_names(unknown);
  return c;
}

CamDesign read_cam(const XmlElementReader& r, const std::string& file,
                   std::vector<UnknownName>& unknown) {
  CamDesign d;
  d.type = r.choice("type", {"plate", "cylindrical"}, "plate") == "plate" ? CamType::Plate
                                                                          : CamType::Cylindrical;
  const std::string follower = r.choice(
      "follower",
      {"knife-edge", "roller", "flat-faced", "oscillating-roller", "oscillating-flat-faced"});
  for (FollowerKind kind : {FollowerKind::KnifeEdge, FollowerKind::Roller, FollowerKind::FlatFaced,
                            FollowerKind::OscillatingRoller, FollowerKind::OscillatingFlatFaced})
    if (follower == follower_kind_name(kind)) d.follower.kind = kind;
  if (has_roller(d.follower.kind)) d.follower.roller_radius = r.positive("roller-radius");
  if (is_oscillating(d.follower.kind)) {
    read_arm(r, d.follower);
  } else {
    d.follower.offset = r.number("offset", 0.0);
  }
  d.rotation = r.choice("rotation", {"ccw", "cw"}, "ccw") == "ccw" ? Rotation::CounterClockwise
                                                                    : Rotation::Clockwise;
  d.rpm = r.positive("rpm", 300.0);
  if (!(d.rpm <= kMaxRpm)) r.fail("rpm", "a speed in (0, " + number_text(kMaxRpm) + "] rev/min");
  if (d.type == CamType::Plate) {
    d.base_radius = r.positive("base-radius");
    d.groove_depth = r.positive("groove-depth", 0.0, true);  // a face groove (plate_groove.h)
    if (d.groove_depth > 0 && !has_roller(d.follower.kind))
      r.fail("groove-depth", "no groove for a " + std::string(follower_kind_name(d.follower.kind)) +
                                 " follower: a grooved plate cam needs a roller or "
                                 "oscillating-roller follower");
    if (const XMLElement* conjugate = r.child("conjugate"))
      d.conjugate = read_conjugate(XmlElementReader(conjugate, file), d, unknown);
  } else {
    d.base_radius = r.positive("base-radius", 0.0, true);
    d.cylinder_radius = r.positive("cylinder-radius");
    d.z0 = r.number("z0", 0.0);
    if (d.follower.kind != FollowerKind::Roller)
      r.fail("follower", "a (translating) roller follower for a cylindrical cam");
    d.groove_depth = r.positive("groove-depth", 0.0, true);
    // The walls' inner radius must keep the contact single-valued (groove_wall.h).
    const double inner_limit = std::sqrt(2.0) * d.follower.roller_radius;
    if (d.groove_depth > 0 && !(d.cylinder_radius - d.groove_depth / 2 >= inner_limit))
      r.fail("groove-depth", "a depth whose inner radius cylinder-radius − depth/2 is at least "
                             "√2·roller-radius = " + number_text(inner_limit) + " mm (at most " +
                             number_text(2 * (d.cylinder_radius - inner_limit)) + " mm)");
  }

  const std::vector<const XMLElement*> segments = r.children("segment");
  if (segments.empty()) throw InputError(r.where() + ": no <segment> elements");
  double at = 0.0, level = 0.0;
  for (const XMLElement* e : segments) {
    const XmlElementReader s(e, file);
    SegmentSpec spec = read_segment(s, at, level, file, unknown);
    if (std::abs(spec.start - at) > 1e-9)
      throw InputError(s.where() + ": segment starts at " + degrees_text(spec.start) +
                       " but the previous one ends at " + degrees_text(at) + " (" +
                       (spec.start > at ? "a gap" : "an overlap") + ")");
    at = spec.end;
    level += spec.kind == SegmentKind::Rise ? spec.lift : spec.kind == SegmentKind::Return ? -spec.lift : 0;
    s.collect_unknown_names(unknown);
    d.segments.push_back(std::move(spec));
  }
  if (std::abs(at - 2 * std::numbers::pi) > 1e-9)
    throw InputError(r.where() + ": the segments end at " + degrees_text(at) +
                     "; they must cover 0° to 360°");
  try {
    make_program(d);
  } catch (const InputError& e) {
    throw InputError(r.where() + ": " + e.what());
  }
  return d;
}

// `unit`: millimetres per length unit of the file; the floor applies to the tolerance in mm.
void read_conversion(const XmlElementReader& r, double unit, CamProject& p) {
  if (r.has("tolerance")) p.conversion.tolerance = r.positive("tolerance") * unit;
  if (p.conversion.tolerance < kMinTolerance)
    r.fail("tolerance", "a tolerance >= " + number(kMinTolerance) + " mm");
  p.conversion.base = r.choice("base", {"quasi-uniform", "rqb"}, "quasi-uniform") == "rqb"
                          ? ArcKind::rqb
                          : ArcKind::quartic;
  p.conversion.alpha = r.choice("alpha", {"minimax", "printed"}, "minimax") == "printed"
                           ? AlphaRule::printed
                           : AlphaRule::minimax;
  p.conversion.compaction = read_compaction(r);
  if (r.has("max-degree")) {
    const int degree = r.integer("max-degree", 0);
    if (degree < 1) r.fail("max-degree", "an integer >= 1, or empty for the exact degree");
    p.max_degree = degree;
  } else {
    r.text("max-degree", "");  // an empty value means "exact degree"
  }
}

// Every length of a design read in another unit, in mm: the jobs work in mm only.
// An oscillating follower's lifts and endpoint derivatives are angles (degrees), not lengths.
void to_millimetres(CamDesign& d, double unit) {
  for (double* length : {&d.base_radius, &d.follower.roller_radius, &d.follower.offset,
                         &d.follower.pivot_distance, &d.follower.arm_length,
                         &d.follower.face_offset, &d.cylinder_radius, &d.z0, &d.groove_depth})
    *length *= unit;
  if (d.conjugate)
    for (double* length :
         {&d.conjugate->roller_distance, &d.conjugate->arm_length, &d.conjugate->roller_radius})
      *length *= unit;
  if (is_oscillating(d.follower.kind)) return;
  for (SegmentSpec& s : d.segments) {
    s.lift *= unit;
    for (EndpointDerivatives* e : {&s.at_start, &s.at_end})
      for (double* derivative : {&e->velocity, &e->acceleration, &e->jerk}) *derivative *= unit;
  }
}

}  // namespace

CamProject parse_cam_project(const std::string& text, const std::string& file,
                             std::vector<std::string>& warnings, UnknownNames policy) {
  const XmlDocument doc(text, file);
  const XmlElementReader root(doc.root(), file);
  if (std::string(doc.root()->Name()) != "polarform")
    throw InputError(root.where() + ": expected the root element <polarform>");
  check_project_version(root, policy, warnings);
  const XMLElement* cam = root.child("cam");
  if (!cam) throw InputError(root.where() + ": no <cam> element");
  CamProject p;
  std::vector<UnknownName> unknown;
  const XmlElementReader cam_reader(cam, file);
  p.cam = read_cam(cam_reader, file, unknown);
  const double unit = read_length_unit(root, cam_reader);
  to_millimetres(p.cam, unit);
  if (p.cam.type ==
      CamType::Plate) {  // the follower's geometry against the base circle and the lift
    try {
      make_plate_cam(p.cam);
    } catch (const InputError& e) {
      throw InputError(cam_reader.where() + ": " + e.what());
    }
  }
  if (const auto limit = cam_reader.optional_number("pressure-angle-limit")) {
    if (!(*limit > 0 && *limit < 90))
      cam_reader.fail("pressure-angle-limit", "an angle in (0, 90) degrees");
    p.pressure_angle_limit = *limit * kRadiansPerDegree;
  }
  cam_reader.collect_unknown_names(unknown);
  if (const XMLElement* conversion = root.child("conversion")) {
    const XmlElementReader r(conversion, file);
    read_conversion(r, unit, p);
    r.collect_unknown_names(unknown);
  }
  if (const XMLElement* dynamics = root.child("dynamics")) {
    const XmlElementReader r(dynamics, file);
    p.load = read_dynamics(r, unit, is_oscillating(p.cam.follower.kind));
    r.collect_unknown_names(unknown);
  }
  root.collect_unknown_names(unknown);
  settle_unknown_names(unknown, policy, warnings);
  return p;
}

CamProject read_cam_project(const std::filesystem::path& file, std::vector<std::string>& warnings,
                            UnknownNames policy) {
  if (!std::filesystem::is_regular_file(file)) throw InputError(file.string() + ": no such file");
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return parse_cam_project(text.str(), file.string(), warnings, policy);
}

std::string cam_project_xml(const CamProject& p) {
  std::ostringstream out;
  const CamDesign& d = p.cam;
  auto attr = [&](const char* name, const std::string& value) {
    out << ' ' << name << "=\"" << xml_escape(value) << '"';
  };
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<!-- polarform cam project: lengths in mm, angles in degrees, endpoint derivatives per "
         "radian -->\n<polarform version=\"1\">\n  <cam";
  attr("type", std::string(cam_type_name(d.type)));
  attr("follower", std::string(follower_kind_name(d.follower.kind)));
  if (d.type == CamType::Plate || d.base_radius > 0) attr("base-radius", number(d.base_radius));
  if (has_roller(d.follower.kind)) attr("roller-radius", number(d.follower.roller_radius));
  if (is_oscillating(d.follower.kind)) {
    attr("pivot-distance", number(d.follower.pivot_distance));
    if (d.follower.kind == FollowerKind::OscillatingRoller)
      attr("arm-length", number(d.follower.arm_length));
    else
      attr("face-offset", number(d.follower.face_offset));
    attr("pivot-side", d.follower.pivot_side > 0 ? "right" : "left");
  } else {
    attr("offset", number(d.follower.offset));
  }
  attr("rotation", std::string(rotation_name(d.rotation)));
  attr("rpm", number(d.rpm));
  if (p.pressure_angle_limit)
    attr("pressure-angle-limit", number(degrees_for(*p.pressure_angle_limit)));
  if (d.type == CamType::Cylindrical) {
    attr("cylinder-radius", number(d.cylinder_radius));
    attr("z0", number(d.z0));
  }
  if (d.groove_depth > 0) attr("groove-depth", number(d.groove_depth));
  out << ">\n";
  if (d.conjugate) {
    out << "    <conjugate";
    if (d.follower.kind == FollowerKind::OscillatingRoller) {
      attr("arm-angle", number(degrees_for(d.conjugate->arm_angle)));
      attr("arm-length", number(d.conjugate->arm_length));
    } else {
      attr("roller-distance", number(d.conjugate->roller_distance));
    }
    if (d.conjugate->roller_radius > 0) attr("roller-radius", number(d.conjugate->roller_radius));
    out << "/>\n";
  }
  for (const SegmentSpec& s : d.segments) {
    out << "    <segment";
    attr("kind", std::string(segment_kind_name(s.kind)));
    if (!s.name.empty()) attr("name", s.name);
    if (s.kind != SegmentKind::Dwell) {
      attr("law", std::string(motion_law_name(s.law)));
      attr("lift", number(s.lift));
    }
    attr("from", number(degrees_for(s.start)));
    attr("to", number(degrees_for(s.end)));
    const bool constrained =
        (s.law == MotionLaw::Polynomial && s.kind != SegmentKind::RiseReturn) ||
        s.law == MotionLaw::BSpline;
    if (s.kind != SegmentKind::Dwell && s.law == MotionLaw::Scca) {
      attr("b", number(s.scca.b));
      attr("c", number(s.scca.c));
      attr("d", number(s.scca.d));
    }
    if (s.kind != SegmentKind::Dwell && s.law == MotionLaw::ConstantVelocity)
      attr("blend", number(s.blend));
    if (s.kind != SegmentKind::Dwell && s.law == MotionLaw::Table) {
      attr("file", s.table.file);
      attr("ends", s.table.ends == TableEnds::Rest ? "rest" : "free");
    }
    if (s.kind != SegmentKind::Dwell && s.law == MotionLaw::Polynomial && s.polynomial_degree > 0)
      attr("degree", std::to_string(s.polynomial_degree));
    if (s.kind != SegmentKind::Dwell && s.law == MotionLaw::BSpline) {
      attr("degree", std::to_string(s.bspline.degree));
      attr("control-values", std::to_string(s.bspline.control_values));
      attr("minimise", std::to_string(s.bspline.minimised_derivative));
    }
    if (s.kind == SegmentKind::Dwell || !constrained) {
      out << "/>\n";
      continue;
    }
    out << ">\n";
    for (auto [tag, e] : {std::pair{"start", &s.at_start}, std::pair{"end", &s.at_end}}) {
      out << "      <" << tag;
      if (s.constrained_order >= 1) attr("v", number(e->velocity));
      if (s.constrained_order >= 2) attr("a", number(e->acceleration));
      if (s.constrained_order >= 3) attr("j", number(e->jerk));
      out << "/>\n";
    }
    if (s.law == MotionLaw::Polynomial)
      for (const PolynomialConstraint& c : s.interior) {
        out << "      <constraint";
        attr("x", number(c.x));
        attr("derivative", std::to_string(c.derivative));
        attr("value", number(c.value));
        out << "/>\n";
      }
    out << "    </segment>\n";
  }
  out << "  </cam>\n  <conversion";
  attr("tolerance", number(p.conversion.tolerance));
  attr("base", p.conversion.base == ArcKind::rqb ? "rqb" : "quasi-uniform");
  attr("alpha", p.conversion.alpha == AlphaRule::printed ? "printed" : "minimax");
  attr("compaction", p.conversion.compaction == Compaction::none    ? "none"
                     : p.conversion.compaction == Compaction::refit ? "refit"
                                                                    : "knot-removal");
  attr("max-degree", p.max_degree ? std::to_string(*p.max_degree) : "");
  out << "/>\n";
  if (p.load) {
    out << "  <dynamics";
    if (p.load->arm) {
      attr("inertia", number(p.load->inertia));
      attr("torsion-rate", number(p.load->torsion_rate));
      attr("preload-torque", number(p.load->preload_torque));
      attr("torsion-damping", number(p.load->torsion_damping));
    } else {
      attr("mass", number(p.load->mass));
      attr("spring-rate", number(p.load->spring_rate));
      attr("preload", number(p.load->preload));
      attr("damping", number(p.load->damping));
    }
    attr("contact-width", number(p.load->contact_width));
    attr("youngs-modulus", number(p.load->youngs_modulus));
    attr("poisson-ratio", number(p.load->poisson_ratio));
    out << "/>\n";
  }
  out << "</polarform>\n";
  return out.str();
}

void write_cam_project(const CamProject& project, const std::filesystem::path& file) {
  write_file_atomically(file, cam_project_xml(project));
}

}  // namespace polarform
