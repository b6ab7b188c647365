#include "jobs/cam/cam_key_figures.h"

#include <cmath>

#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

std::string mm(double v) { return number_text(v) + " mm"; }

// A follower motion value: mm, or degrees of arm swing for an oscillating follower.
std::string motion(double v, const CamDesign& d) {
  return is_oscillating(d.follower.kind) ? number_text(v) + "°" : mm(v);
}

// "|x| in time units (per radian) at θ": v·ω, a·ω², j·ω³ in m/s^k from a law in mm/rad^k, or in
// rad/s^k from an arm swing in °/rad^k.
std::string peak(const Extremum& e, int order, double omega, const CamDesign& d) {
  const bool arm = is_oscillating(d.follower.kind);
  const double in_time = e.value * std::pow(omega, order) * (arm ? kRadiansPerDegree : 1e-3);
  static const char* const kTime[2][3] = {{"m/s", "m/s²", "m/s³"}, {"rad/s", "rad/s²", "rad/s³"}};
  static const char* const kPerRadian[2][3] = {{"mm/rad", "mm/rad²", "mm/rad³"},
                                               {"°/rad", "°/rad²", "°/rad³"}};
  return number_text(in_time) + " " + kTime[arm][order - 1] + " (" + number_text(e.value) + " " +
         kPerRadian[arm][order - 1] + ") at θ = " + degrees_text(e.theta);
}

std::string at(const Extremum& e) {
  return std::isinf(e.value) ? "none (no convex part)"
                             : mm(e.value) + " at θ = " + degrees_text(e.theta);
}

std::string follower_text(const CamDesign& d) {
  std::string text = std::string(follower_kind_name(d.follower.kind)) + " follower";
  if (has_roller(d.follower.kind)) text += ", roller radius " + mm(d.follower.roller_radius);
  if (d.follower.offset != 0.0) text += ", offset " + mm(d.follower.offset);
  if (is_oscillating(d.follower.kind)) {
    text += ", pivot " + mm(d.follower.pivot_distance) + " from the cam centre (" +
            (d.follower.pivot_side > 0 ? "right" : "left") + ")";
    text += d.follower.kind == FollowerKind::OscillatingRoller
                ? ", arm length " + mm(d.follower.arm_length)
                : ", face offset " + mm(d.follower.face_offset);
  }
  return text;
}

}  // namespace

std::vector<KeyFigure> cam_design_inputs(const CamDesignStage& design) {
  const CamDesign& d = design.project.cam;
  std::vector<KeyFigure> out;
  if (d.type == CamType::Plate) {
    out.push_back({"cam", "plate cam, base radius " + mm(d.base_radius) + ", " + follower_text(d)});
  } else {
    out.push_back({"cam", "cylindrical cam, pitch cylinder radius " + mm(d.cylinder_radius) + ", " +
                              follower_text(d)});
  }
  if (d.type == CamType::Plate && d.groove_depth > 0)
    out.push_back({"groove", "face groove " + mm(d.groove_depth) +
                                 " deep between the flanks pitch ∓ roller radius"});
  if (d.conjugate)
    out.push_back({"conjugate cam", is_oscillating(d.follower.kind)
                                        ? "second arm " + mm(d.conjugate->arm_length) + " long, " +
                                              degrees_text(d.conjugate->arm_angle) +
                                              " from the first about the pivot"
                                        : "second roller " + mm(d.conjugate->roller_distance) +
                                              " beyond the first on the follower axis"});
  if (d.conjugate && d.conjugate->roller_radius > 0)
    out.push_back({"second roller radius", mm(d.conjugate->roller_radius)});
  out.push_back({"speed", number_text(d.rpm) + " rev/min, " +
                              (d.rotation == Rotation::CounterClockwise ? "counter-clockwise"
                                                                        : "clockwise")});
  for (const MotionSegment& s : design.program.segments()) {
    const SegmentSpec& spec = s.spec();
    std::string value = std::string(segment_kind_name(spec.kind));
    if (spec.kind != SegmentKind::Dwell) {
      value += ", " + std::string(motion_law_name(spec.law));
      if (spec.law == MotionLaw::Scca)
        value += " (b " + number_text(spec.scca.b) + ", c " + number_text(spec.scca.c) + ", d " +
                 number_text(spec.scca.d) + ")";
      value += ", lift " + motion(spec.lift, d);
    }
    value += ", θ " + degrees_text(spec.start) + " to " + degrees_text(spec.end);
    out.push_back({"segment '" + s.name() + "'", value});
  }
  return out;
}

std::vector<KeyFigure> cam_dynamics_figures(const FollowerDynamics& dyn, const FollowerLoad& load) {
  std::vector<KeyFigure> out;
  std::string force =
      number_text(dyn.least_force.force) + " N at θ = " + degrees_text(dyn.least_force.theta);
  force += dyn.jumps ? ": the follower JUMPS" : "";
  if (dyn.conjugate)
    force += " (below 0 the second cam holds the follower)";
  else
    force += dyn.jump_rpm ? "; it jumps from " + number_text(*dyn.jump_rpm) + " rpm"
                          : "; it never jumps";
  out.push_back({"min contact force", force});
  out.push_back(
      {load.arm ? "least torsion rate for contact" : "least spring rate for contact",
       number_text(dyn.min_spring_rate) + (load.arm ? " N·m/rad" : " N/mm") + " (same preload)"});
  out.push_back({"max camshaft torque", number_text(dyn.largest_torque.torque) + " N·m at θ = " +
                                            degrees_text(dyn.largest_torque.theta)});
  if (dyn.largest_stress.contact_stress > 0)
    out.push_back(
        {"max contact stress", number_text(dyn.largest_stress.contact_stress) +
                                   " MPa at θ = " + degrees_text(dyn.largest_stress.theta)});
  if (dyn.conjugate) {
    out.push_back({"second roller max force",
                   number_text(dyn.largest_second_force.second_force) +
                       " N at θ = " + degrees_text(dyn.largest_second_force.theta)});
    if (dyn.largest_second_stress.second_stress > 0)
      out.push_back({"second roller max stress",
                     number_text(dyn.largest_second_stress.second_stress) +
                         " MPa at θ = " + degrees_text(dyn.largest_second_stress.theta)});
  }
  return out;
}

std::vector<KeyFigure> cam_key_results(const CamDesignStage& design,
                                       const CamAnalysisStage& analysis,
                                       const CamConversionStage* conversion) {
  const CamDesign& cam = design.project.cam;
  const double omega = angular_speed(cam.rpm);
  const MotionExtrema& m = analysis.motion_extrema();
  std::vector<KeyFigure> out = {{is_oscillating(cam.follower.kind) ? "arm swing" : "stroke",
                                 motion(design.program.stroke(), cam)},
                                {"peak velocity", peak(m.velocity, 1, omega, cam)},
                                {"peak acceleration", peak(m.acceleration, 2, omega, cam)},
                                {"peak jerk", peak(m.jerk, 3, omega, cam)}};
  const Extremum pressure = analysis.max_pressure_angle();
  std::string pressure_text =
      degrees_text(pressure.value) + " at θ = " + degrees_text(pressure.theta);
  if (!std::holds_alternative<PlateCamAnalysis>(analysis.cam)) pressure_text += " (pitch radius)";
  if (analysis.pressure_angle_limit)
    pressure_text += !analysis.pressure_angle_within_limit()
                         ? ", BEYOND the limit " + degrees_text(*analysis.pressure_angle_limit)
                         : ", limit " + degrees_text(*analysis.pressure_angle_limit);
  out.push_back({"max pressure angle", pressure_text});
  if (const auto* p = std::get_if<PlateCamAnalysis>(&analysis.cam)) {
    if (has_roller(cam.follower.kind))
      out.push_back(
          {"min radius of curvature, pitch curve", at(p->analysis.min_convex_pitch_radius)});
    if (const auto& b = p->pipe_bound)
      out.push_back({"pipe bound 1/κ_max, pitch curve (|κ|, either side)", mm(b->r_local)});
    out.push_back({"min radius of curvature, contour", at(p->analysis.min_convex_contour_radius)});
    std::string undercut = "none";
    if (!p->analysis.undercut.empty()) {
      undercut = "YES at θ";
      for (const AngleRange& u : p->analysis.undercut)
        undercut += " " + degrees_text(u.from) + " to " + degrees_text(u.to);
    }
    out.push_back({"undercut", undercut});
    if (const std::optional<FaceWidth>& face = p->analysis.face_width)
      out.push_back({"face width needed",
                     mm(face->width()) + ": contact from " + mm(face->left) + " to " +
                         mm(face->right) +
                         (is_oscillating(cam.follower.kind) ? " along the face from the pivot"
                                                            : " from the follower axis")});
  }
  if (const auto& dyn = analysis.dynamics)
    for (KeyFigure& f : cam_dynamics_figures(*dyn, *design.project.load))
      out.push_back(std::move(f));
  if (conversion) {
    const PolarConversion& c = conversion->conversion;
    // The conversion's steps: the product C = F·B on its base-circle arcs, then the refit or the
    // knot removal that made it compact.
    std::string steps = std::to_string(c.arcs.size()) + " base-circle arcs";
    for (std::size_t k = 0; k < c.steps.size(); ++k)
      steps += (k == 0 ? "; " : " → ") + c.steps[k].name + " " +
               std::to_string(c.steps[k].control_points);
    out.push_back({"NURBS profile", "degree " + std::to_string(conversion->degree()) + ", " +
                                        std::to_string(conversion->control_points()) +
                                        " control points (" + steps + ")"});
    out.push_back({"measured error", "max radial " + mm(c.max_radial_error) + ", max normal " +
                                         mm(c.max_normal_error) + " (tolerance " + mm(c.tolerance) +
                                         ")"});
    if (const auto& second = conversion->companion) {
      const PolarConversion& k = second->conversion;
      out.push_back({second->kind == CompanionKind::GrooveOuterFlank ? "NURBS groove outer flank"
                                                                     : "NURBS conjugate contour",
                     "degree " + std::to_string(k.curve.degree()) + ", " +
                         std::to_string(k.curve.size()) + " control points, measured max radial " +
                         mm(k.max_radial_error) + ", max normal " + mm(k.max_normal_error)});
      if (const auto& cd = second->centre_distance)
        out.push_back({"rollers' centre distance", "measured max error " + mm(cd->max_error) +
                                                       " at θ = " + degrees_text(cd->theta) +
                                                       " (contours at " + number_text(cd->share) +
                                                       " × the tolerance)"});
    }
  }
  return out;
}

}  // namespace polarform
