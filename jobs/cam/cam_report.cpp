#include "jobs/cam/cam_report.h"

#include <cmath>

#include "jobs/report/conversion_report.h"
#include "polarform_version.h"
#include "src/units.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

json extremum(const Extremum& e, double scale, const char* unit) {
  return json{{std::string("value_") + unit, e.value * scale},
              {"at_deg", e.theta * kDegreesPerRadian}};
}

// The design: cam, segments and the continuity of the motion program.
void add_design_fields(json& j, const CamDesignStage& r) {
  const CamDesign& d = r.project.cam;
  j["cam"] = {{"type", cam_type_name(d.type)},
              {"follower", follower_kind_name(d.follower.kind)},
              {"base_radius_mm", d.base_radius},
              {"roller_radius_mm", d.follower.roller_radius},
              {"offset_mm", d.follower.offset},
              {"rotation", rotation_name(d.rotation)},
              {"rpm", d.rpm},
              {"motion_unit", motion_unit(d.follower.kind)}};
  if (is_oscillating(d.follower.kind)) {
    const PlateCam& cam = std::get<PlateCam>(r.cam);
    j["cam"]["pivot_distance_mm"] = d.follower.pivot_distance;
    if (d.follower.kind == FollowerKind::OscillatingRoller)
      j["cam"]["arm_length_mm"] = d.follower.arm_length;
    else
      j["cam"]["face_offset_mm"] = d.follower.face_offset;
    j["cam"]["pivot_side"] = d.follower.pivot_side > 0 ? "right" : "left";
    j["cam"]["pivot_mm"] = {cam.pivot().x(), cam.pivot().y()};
    j["cam"]["max_arm_swing_deg"] = cam.max_arm_swing();
  }
  if (d.type == CamType::Cylindrical) {
    j["cam"]["cylinder_radius_mm"] = d.cylinder_radius;
    j["cam"]["z0_mm"] = d.z0;
  }
  j["segments"] = json::array();
  for (const MotionSegment& s : r.program.segments()) {
    j["segments"].push_back(
        {{"name", s.name()},
         {"kind", segment_kind_name(s.spec().kind)},
         {"law", s.spec().kind == SegmentKind::Dwell ? "" : motion_law_name(s.spec().law)},
         {"start_deg", s.start() * kDegreesPerRadian},
         {"end_deg", s.end() * kDegreesPerRadian},
         {std::string("lift_") + std::string(motion_unit(d.follower.kind)), s.spec().lift}});
    if (s.spec().kind != SegmentKind::Dwell && s.spec().law == MotionLaw::Scca)
      j["segments"].back()["scca"] = {
          {"b", s.spec().scca.b}, {"c", s.spec().scca.c}, {"d", s.spec().scca.d}};
    if (s.spec().kind != SegmentKind::Dwell && s.spec().law == MotionLaw::Polynomial &&
        s.polynomial()) {
      // The normalised law's peak factors from the polynomial itself (in t = x, per unit lift).
      const PolynomialPeaks peaks = polynomial_peaks(*s.polynomial());
      const double lift = s.spec().lift;
      j["segments"].back()["polynomial"] = {
          {"degree", s.polynomial_degree()},
          {"interior_constraints", s.spec().interior.size()},
          {"solved_by", s.least_jerk_energy()                      ? "least jerk energy"
                        : s.spec().kind == SegmentKind::RiseReturn ? "3-4-5-6 single-dwell"
                                                                   : "constraints (exact)"},
          {"cv", peaks.cv / lift},
          {"ca", peaks.ca / lift},
          {"cj", peaks.cj / lift}};
    }
  }
  j["continuity"] = json::array();
  for (const ContinuityIssue& i : r.continuity)
    j["continuity"].push_back({{"angle_deg", i.angle * kDegreesPerRadian},
                               {"derivative", i.derivative},
                               {"jump_per_rad", i.jump()},
                               {"message", i.message()}});
}

// The exact NURBS profile or track and the groove walls.
// A grooved cam's outer flank ("groove") or a conjugate cam's second contour ("conjugate").
void add_companion_fields(json& j, const CamDesign& d, const CompanionCurve& c) {
  json curve;
  const NurbsCurve2d& exact = c.conversion.curve;
  add_conversion_fields(curve, c.conversion, exact.degree(), exact.size(), exact.knots().size());
  if (c.capped)
    curve["exported"] = {{"degree", c.capped->curve.degree()},
                         {"control_points", c.capped->control_points},
                         {"max_radial_error_mm", c.capped->max_radial_error}};
  if (c.kind == CompanionKind::GrooveOuterFlank) {
    j["groove"] = {{"depth_mm", d.groove_depth}, {"outer_flank", std::move(curve)}};
    return;
  }
  j["conjugate"] = is_oscillating(d.follower.kind)
                       ? json{{"arm_angle_deg", d.conjugate->arm_angle * kDegreesPerRadian},
                              {"arm_length_mm", d.conjugate->arm_length}}
                       : json{{"roller_distance_mm", d.conjugate->roller_distance}};
  j["conjugate"]["roller_radius_mm"] =
      d.conjugate->roller_radius > 0 ? d.conjugate->roller_radius : d.follower.roller_radius;
  if (c.centre_distance)
    j["conjugate"]["centre_distance"] = {{"max_error_mm", c.centre_distance->max_error},
                                         {"at_deg", c.centre_distance->theta * kDegreesPerRadian},
                                         {"tolerance_share", c.centre_distance->share},
                                         {"samples", c.centre_distance->samples}};
  j["conjugate"]["contour"] = std::move(curve);
}

void add_profile_fields(json& j, const CamDesignStage& d, const CamConversionStage& c) {
  add_conversion_fields(j, c.conversion, c.degree(), c.control_points(), c.knot_count());
  if (c.companion) add_companion_fields(j, d.project.cam, *c.companion);
  const auto* track = std::get_if<CylindricalTrack>(&c.profile);
  if (!track || track->groove.empty()) return;
  const GrooveSurface& g = track->groove.front();
  j["groove"] = {{"depth_mm", d.project.cam.groove_depth},
                 {"inner_radius_mm", g.surface.front_v()},
                 {"outer_radius_mm", g.surface.back_v()},
                 {"tolerance_mm", g.tolerance},
                 {"walls", json::array()}};
  for (const GrooveSurface& w : track->groove)
    j["groove"]["walls"].push_back({{"side", w.side > 0 ? "+z" : "-z"},
                                    {"degree_u", w.surface.degree_u()},
                                    {"degree_v", w.surface.degree_v()},
                                    {"control_points_u", w.surface.size_u()},
                                    {"control_points_v", w.surface.size_v()},
                                    {"arcs", w.base.arcs()},
                                    {"height_degree_u", w.height.degree_u()},
                                    {"height_degree_v", w.height.degree_v()},
                                    {"max_error_mm", w.max_error},
                                    {"height_fit_error_mm", w.fit_error},
                                    {"samples", w.samples}});
}

// The analyses: pressure angle, radii of curvature, undercut, face width, SVAJ extremes, speed.
void add_analysis_fields(json& j, const CamDesignStage& d, const CamAnalysisStage& r) {
  const std::string u(motion_unit(d.project.cam.follower.kind));
  if (const auto* p = std::get_if<PlateCamAnalysis>(&r.cam)) {
    const CamAnalysis& a = p->analysis;
    const auto finite_or_null = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
    j["max_pressure_angle_deg"] = a.max_pressure_angle.value * kDegreesPerRadian;
    j["max_pressure_angle_at_deg"] = a.max_pressure_angle.theta * kDegreesPerRadian;
    j["min_radius_of_curvature_mm"] = a.min_convex_contour_radius.value;
    j["min_radius_of_curvature_at_deg"] = a.min_convex_contour_radius.theta * kDegreesPerRadian;
    j["min_concave_radius_of_curvature_mm"] = finite_or_null(a.min_concave_contour_radius.value);
    j["min_pitch_radius_of_curvature_mm"] = finite_or_null(a.min_convex_pitch_radius.value);
    j["pipe_bound"] = nullptr;
    if (const auto& b = p->pipe_bound)
      j["pipe_bound"] = {{"kappa_max_per_mm", finite_or_null(b->kappa_max)},
                         {"r_local_mm", b->r_local}};
    j["undercut"] = !a.undercut.empty();
    j["undercut_ranges_deg"] = json::array();
    for (const AngleRange& u : a.undercut)
      j["undercut_ranges_deg"].push_back({u.from * kDegreesPerRadian, u.to * kDegreesPerRadian});
    if (a.face_width)
      j["face_width_mm"] = {{"left", a.face_width->left}, {"right", a.face_width->right}};
    j["motion"] = {
        {"max_velocity", extremum(a.motion.velocity, 1, (u + "_per_rad").c_str())},
        {"max_acceleration", extremum(a.motion.acceleration, 1, (u + "_per_rad2").c_str())},
        {"max_jerk", extremum(a.motion.jerk, 1, (u + "_per_rad3").c_str())}};
  } else {
    j["max_pressure_angle_deg"] = r.max_pressure_angle().value * kDegreesPerRadian;
    j["undercut"] = false;
  }
  if (r.pressure_angle_limit) {
    j["pressure_angle_limit_deg"] = *r.pressure_angle_limit * kDegreesPerRadian;
    j["pressure_angle_within_limit"] = r.pressure_angle_within_limit();
  } else {
    j["pressure_angle_limit_deg"] = nullptr;  // a flat-faced follower: fixed by its geometry
  }
  j["speed_rad_per_s"] = angular_speed(d.project.cam.rpm);
  j["dynamics"] = nullptr;
  if (const auto& dyn = r.dynamics) {
    const FollowerLoad& load = *d.project.load;
    // The spring and the least rate that keeps contact: N/mm, or N·m/rad for an arm.
    j["dynamics"] = load.arm ? json{{"inertia_kg_m2", load.inertia},
                                    {"torsion_rate_nm_per_rad", load.torsion_rate},
                                    {"preload_torque_nm", load.preload_torque},
                                    {"torsion_damping_nms_per_rad", load.torsion_damping}}
                             : json{{"mass_kg", load.mass},
                                    {"spring_rate_n_per_mm", load.spring_rate},
                                    {"preload_n", load.preload},
                                    {"damping_ns_per_mm", load.damping}};
    j["dynamics"].update(
        {{"min_contact_force_n", dyn->least_force.force},
         {"min_contact_force_at_deg", dyn->least_force.theta * kDegreesPerRadian},
         {"jumps", dyn->jumps},
         {"jump_rpm", dyn->jump_rpm ? json(*dyn->jump_rpm) : json(nullptr)},
         {load.arm ? "min_torsion_rate_nm_per_rad" : "min_spring_rate_n_per_mm",
          dyn->min_spring_rate},
         {"max_torque_nm", dyn->largest_torque.torque},
         {"max_torque_at_deg", dyn->largest_torque.theta * kDegreesPerRadian},
         {"max_contact_stress_mpa", dyn->largest_stress.contact_stress},
         {"max_contact_stress_at_deg", dyn->largest_stress.theta * kDegreesPerRadian}});
    if (dyn->conjugate)
      j["dynamics"]["second_roller"] = {
          {"max_contact_force_n", dyn->largest_second_force.second_force},
          {"max_contact_force_at_deg", dyn->largest_second_force.theta * kDegreesPerRadian},
          {"max_contact_stress_mpa", dyn->largest_second_stress.second_stress},
          {"max_contact_stress_at_deg", dyn->largest_second_stress.theta * kDegreesPerRadian}};
  }
}

// The degree-limited and capped profiles.
void add_profile_extras(json& j, const CamConversionStage& c) {
  const auto* profile = std::get_if<PlateProfile>(&c.profile);
  if (profile && profile->limited)
    j["degree_limited"] = {{"degree", profile->limited->curve.degree()},
                           {"control_points", profile->limited->control_points},
                           {"max_radial_error_mm", profile->limited->max_radial_error},
                           {"max_normal_error_mm", profile->limited->max_normal_error}};
  if (profile && profile->capped)
    j["exported_profile"] = {{"degree", profile->capped->curve.degree()},
                             {"control_points", profile->capped->control_points},
                             {"max_radial_error_mm", profile->capped->max_radial_error},
                             {"reason", "the exact degree exceeds the project's max-degree"}};
}

}  // namespace

json cam_report_fields(const CamDesignStage& design, const CamAnalysisStage& analysis,
                       const CamConversionStage* conversion) {
  json j;
  // Which angle the *_deg fields are (docs/cli.md, "Angles and the follower's position").
  j["angles"] = {
      {"theta",
       "cam angle θ: the cam's rotation from its position at θ = 0, where the follower is on "
       "+y; segments, continuity, motion and pressure-angle extremes, radii of curvature, "
       "undercut"},
      {"psi",
       design.project.cam.type == CamType::Plate
           ? "polar angle ψ of a contour point in the cam frame, from +x towards +y; arc_list, "
             "worst_angle_deg"
           : "polar angle ψ around the cylinder axis in the cam frame, from +x towards +y; "
             "arc_list, worst_angle_deg"}};
  add_design_fields(j, design);
  if (conversion) add_profile_fields(j, design, *conversion);
  add_analysis_fields(j, design, analysis);
  if (conversion) add_profile_extras(j, *conversion);
  // What the analyses found beyond their limits and what the conversion left out.
  std::vector<std::string> warnings = analysis.warnings;
  if (conversion)
    warnings.insert(warnings.end(), conversion->warnings.begin(), conversion->warnings.end());
  j["warnings"] = warnings;
  return j;
}

json cam_report_json(const CamJobResult& r, const std::vector<std::string>& files) {
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "cam";
  j["feasible"] = true;
  j.update(cam_report_fields(r.design, r.analysis, &r.conversion));
  j["files"] = files;
  j["seconds"] = r.seconds;
  return j;
}

json cam_infeasible_report_json(const InfeasibleCam& cam, const std::vector<std::string>& files) {
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "cam";
  j["feasible"] = false;
  j["infeasible_reason"] = cam.reason;
  j.update(cam_report_fields(cam.design, cam.analysis, nullptr));
  j["files"] = files;
  return j;
}

}  // namespace polarform
