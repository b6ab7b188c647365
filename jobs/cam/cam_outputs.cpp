#include "jobs/cam/cam_outputs.h"

#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "export/atomic_file.h"
#include "export/csv_writer.h"
#include "export/dxf_writer.h"
#include "export/html_report.h"
#include "export/iges_writer.h"
#include "export/step_solid.h"
#include "export/step_writer.h"
#include "export/x3d_writer.h"
#include "jobs/cam/cam_plots.h"
#include "jobs/report/conversion_report.h"
#include "polarform_version.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

json extremum(const Extremum& e, double scale, const char* unit) {
  return json{{std::string("value_") + unit, e.value * scale},
              {"at_deg", e.theta * kDegreesPerRadian}};
}

// The curve the CAD files carry: the exact profile, or its degree-capped approximation.
const NurbsCurve2d& exported_profile(const CamJobResult& r) {
  return r.capped ? r.capped->curve : r.profile;
}

std::string svaj_csv(const CamJobResult& r) {
  std::vector<std::string> headers = {"theta [deg]", "s [mm]", "v [mm/s]", "a [mm/s^2]",
                                      "j [mm/s^3]", "ds/dtheta [mm/rad]", "d2s/dtheta2 [mm/rad^2]",
                                      "d3s/dtheta3 [mm/rad^3]"};
  if (r.analysis)
    for (const char* h : {"pressure angle [deg]", "contour radius of curvature [mm]",
                          "pitch radius of curvature [mm]"})
      headers.push_back(h);
  if (r.barrel) headers.push_back("pressure angle at pitch radius [deg]");
  CsvWriter csv(headers);
  for (std::size_t i = 0; i < r.angles.size(); ++i) {
    double d[4];
    r.program.derivatives(r.angles[i], 3, d);
    const Kinematics& k = r.kinematics[i];
    std::vector<double> row = {r.angles[i] * kDegreesPerRadian,
                               k.displacement,
                               k.velocity,
                               k.acceleration,
                               k.jerk,
                               d[1],
                               d[2],
                               d[3]};
    if (r.analysis) {
      const CamSample& s = r.analysis->samples[i];
      row.push_back(s.pressure_angle * kDegreesPerRadian);
      row.push_back(1 / s.contour_curvature);
      row.push_back(1 / s.pitch_curvature);
    }
    if (r.barrel) row.push_back(r.barrel_pressure_angle[i] * kDegreesPerRadian);
    csv.row(row);
  }
  return csv.str();
}

std::string html_report(const CamJobResult& r, const CamOutputOptions& o, const json& report,
                        const std::map<std::string, std::string>& svgs) {
  HtmlReport html("polarform cam report: " + o.design_name);
  const PolarConversion& c = r.conversion;
  const bool plate = r.plate.has_value();
  std::vector<std::pair<std::string, std::string>> key = {
      {"tolerance", format_trimmed(c.tolerance * 1e3, 4) + " µm"},
      {"measured max radial error", format_trimmed(c.max_radial_error * 1e3, 4) + " µm"},
      {"measured max normal error", format_trimmed(c.max_normal_error * 1e3, 4) + " µm"},
      {"degree", std::to_string(plate ? r.profile.degree() : r.track.degree())},
      {"control points", std::to_string(plate ? r.profile.size() : r.track.size())},
      {"base-circle arcs", std::to_string(c.arcs.size())},
      {"max tangent jump at arc junctions",
       format_trimmed(c.max_tangent_jump * kDegreesPerRadian, 6) + "°"}};
  if (report.contains("max_pressure_angle_deg"))
    key.emplace_back("max pressure angle",
                     format_trimmed(report["max_pressure_angle_deg"].get<double>(), 2) + "°");
  if (r.analysis)
    key.emplace_back("undercut", r.analysis->undercut.empty() ? "none" : "YES");
  html.add_key_figures(key);
  if (!r.continuity.empty()) {
    html.add_heading("Continuity of the motion program");
    for (const ContinuityIssue& issue : r.continuity) html.add_paragraph(issue.message());
  }
  html.add_heading("Motion");
  html.add_svg(svgs.at("svaj.svg"), "Displacement, velocity, acceleration and jerk against cam angle; grey lines mark segment boundaries.");
  html.add_svg(svgs.at("analysis.svg"), plate ? "Pressure angle and radii of curvature." : "Pressure angle at the pitch radius and track height.");
  html.add_heading("NURBS profile");
  html.add_svg(svgs.at("profile.svg"), plate ? "The exported contour with its control polygon." : "The track centre line, developed.");
  html.add_svg(svgs.at("error.svg"), "Radial error of the NURBS profile, measured against the exact profile.");
  std::vector<std::vector<std::string>> arcs;
  for (const ArcSummary& a : c.arcs)
    arcs.push_back({format_trimmed(degrees_in_turn(a.start), 4),
                    format_trimmed(a.sweep * kDegreesPerRadian, 4),
                    format_trimmed(a.max_radial_error * 1e3, 4)});
  html.add_table({"arc start [deg]", "sweep [deg]", "max radial error [µm]"}, arcs);
  html.add_paragraph("Error budget: law → B-spline " +
                     (c.function_exact ? std::string("exact") : format_trimmed(c.function_error * 1e3, 4) + " µm") +
                     ", base-circle synchronization " + format_trimmed(c.synchronization_error * 1e3, 4) + " µm.");
  if (!r.groove.empty()) {
    html.add_heading("Groove walls");
    std::vector<std::vector<std::string>> walls;
    for (const GrooveSurface& w : r.groove)
      walls.push_back(
          {w.side > 0 ? "+z" : "−z",
           std::to_string(w.surface.degree_u()) + " x " + std::to_string(w.surface.degree_v()),
           std::to_string(w.surface.size_u()) + " x " + std::to_string(w.surface.size_v()),
           format_trimmed(w.max_error * 1e3, 4)});
    html.add_table({"wall", "degrees (u x ρ)", "control net", "measured max error [µm]"}, walls);
    html.add_paragraph("groove.igs and groove.stp hold both walls as rational tensor-product "
                       "surfaces (ρ·X, ρ·Y, Z): x, y exact on the cylinders of radius ρ from " +
                       format_trimmed(r.groove.front().surface.front_v(), 6) + " to " +
                       format_trimmed(r.groove.front().surface.back_v(), 6) +
                       " mm, the height Z fitted to the exact roller envelope; the error is the "
                       "largest height gap at equal polar angle and radius, measured densely.");
  }
  if (r.limited)
    html.add_paragraph("Degree-" + std::to_string(r.limited->curve.degree()) + " profile (profile_deg3.dxf): " +
                       std::to_string(r.limited->control_points) + " control points, measured max radial error " +
                       format_trimmed(r.limited->max_radial_error * 1e3, 4) + " µm.");
  html.add_file_list(report["files"].get<std::vector<std::string>>());
  return html.html();
}

}  // namespace

json cam_report_json(const CamJobResult& r, const std::vector<std::string>& files) {
  const CamDesign& d = r.project.cam;
  const PolarConversion& c = r.conversion;
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "cam";
  j["cam"] = {{"type", cam_type_name(d.type)},
              {"follower", follower_kind_name(d.follower.kind)},
              {"base_radius_mm", d.base_radius},
              {"roller_radius_mm", d.follower.roller_radius},
              {"offset_mm", d.follower.offset},
              {"rotation", rotation_name(d.rotation)},
              {"rpm", d.rpm}};
  if (d.type == CamType::Cylindrical) {
    j["cam"]["cylinder_radius_mm"] = d.cylinder_radius;
    j["cam"]["z0_mm"] = d.z0;
  }
  j["segments"] = json::array();
  for (const MotionSegment& s : r.program.segments())
    j["segments"].push_back(
        {{"name", s.name()},
         {"kind", segment_kind_name(s.spec().kind)},
         {"law", s.spec().kind == SegmentKind::Dwell ? "" : motion_law_name(s.spec().law)},
         {"start_deg", s.start() * kDegreesPerRadian},
         {"end_deg", s.end() * kDegreesPerRadian},
         {"lift_mm", s.spec().lift}});
  j["continuity"] = json::array();
  for (const ContinuityIssue& i : r.continuity)
    j["continuity"].push_back({{"angle_deg", i.angle * kDegreesPerRadian},
                               {"derivative", i.derivative},
                               {"jump_per_rad", i.jump()},
                               {"message", i.message()}});
  // Conversion (the fields the issue fixes first).
  const bool plate = r.plate.has_value();
  add_conversion_fields(j, c, plate ? r.profile.degree() : r.track.degree(),
                        plate ? r.profile.size() : r.track.size(),
                        plate ? r.profile.knots().size() : r.track.knots().size());
  if (!r.groove.empty()) {
    const GrooveSurface& g = r.groove.front();
    j["groove"] = {{"depth_mm", r.project.cam.groove_depth},
                   {"inner_radius_mm", g.surface.front_v()},
                   {"outer_radius_mm", g.surface.back_v()},
                   {"tolerance_mm", g.tolerance},
                   {"walls", json::array()}};
    for (const GrooveSurface& w : r.groove)
      j["groove"]["walls"].push_back(
          {{"side", w.side > 0 ? "+z" : "-z"},
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
  // Analyses.
  if (r.analysis) {
    const CamAnalysis& a = *r.analysis;
    j["max_pressure_angle_deg"] = a.max_pressure_angle.value * kDegreesPerRadian;
    j["max_pressure_angle_at_deg"] = a.max_pressure_angle.theta * kDegreesPerRadian;
    j["min_radius_of_curvature_mm"] = a.min_convex_contour_radius.value;
    j["min_radius_of_curvature_at_deg"] = a.min_convex_contour_radius.theta * kDegreesPerRadian;
    j["min_concave_radius_of_curvature_mm"] =
        std::isfinite(a.min_concave_contour_radius.value) ? json(a.min_concave_contour_radius.value) : json(nullptr);
    j["min_pitch_radius_of_curvature_mm"] =
        std::isfinite(a.min_convex_pitch_radius.value) ? json(a.min_convex_pitch_radius.value) : json(nullptr);
    j["undercut"] = !a.undercut.empty();
    j["undercut_ranges_deg"] = json::array();
    for (const AngleRange& u : a.undercut)
      j["undercut_ranges_deg"].push_back({u.from * kDegreesPerRadian, u.to * kDegreesPerRadian});
    if (a.face_width) j["face_width_mm"] = {{"left", a.face_width->left}, {"right", a.face_width->right}};
    j["motion"] = {{"max_velocity", extremum(a.motion.velocity, 1, "mm_per_rad")},
                   {"max_acceleration", extremum(a.motion.acceleration, 1, "mm_per_rad2")},
                   {"max_jerk", extremum(a.motion.jerk, 1, "mm_per_rad3")}};
  } else {
    double worst = 0;
    for (double p : r.barrel_pressure_angle) worst = std::max(worst, std::abs(p));
    j["max_pressure_angle_deg"] = worst * kDegreesPerRadian;
    j["undercut"] = false;
  }
  const double omega = 2 * std::numbers::pi * d.rpm / 60;
  j["speed_rad_per_s"] = omega;
  j["warnings"] = r.warnings;
  if (r.limited)
    j["degree_limited"] = {{"degree", r.limited->curve.degree()},
                           {"control_points", r.limited->control_points},
                           {"max_radial_error_mm", r.limited->max_radial_error},
                           {"max_normal_error_mm", r.limited->max_normal_error}};
  if (r.capped)
    j["exported_profile"] = {{"degree", r.capped->curve.degree()},
                             {"control_points", r.capped->control_points},
                             {"max_radial_error_mm", r.capped->max_radial_error},
                             {"reason", "the exact degree exceeds the project's max-degree"}};
  j["files"] = files;
  j["seconds"] = r.seconds;
  return j;
}

std::vector<std::string> write_cam_outputs(const CamJobResult& r, const std::filesystem::path& dir,
                                           const CamOutputOptions& o) {
  const bool plate = r.plate.has_value();
  if (o.solid_thickness && !plate) throw InputError("--solid applies to plate cams only");
  // Everything is rendered in memory first, so a failure writes nothing.
  std::map<std::string, std::string> content;
  const std::string stem = plate ? "profile" : "track";
  IgesHeader iges;
  iges.description = "polarform " + std::string(POLARFORM_VERSION) + " cam " + o.design_name;
  StepHeader step;
  step.description = iges.description;
  IgesWriter igs;
  StepWriter stp(o.design_name);
  X3dWriter x3d;
  if (plate) {
    const NurbsCurve2d& curve = exported_profile(r);
    igs.add(curve, "CAM PROFILE");
    stp.add(curve, "cam profile");
    x3d.add(curve, "profile");
    DxfWriter dxf(DxfOptions{std::max(10, curve.degree()), 1e-6});
    dxf.add(curve, "PROFILE");
    dxf.add_circle(Eigen::Vector3d::Zero(), r.project.cam.base_radius, "BASE_CIRCLE");
    content[stem + ".dxf"] = dxf.str();
    if (r.limited) {
      DxfWriter limited;
      limited.add(r.limited->curve, "PROFILE");
      content["profile_deg" + std::to_string(r.limited->curve.degree()) + ".dxf"] = limited.str();
    }
    if (o.solid_thickness)
      content["cam_solid.stp"] = step_extruded_solid(curve, *o.solid_thickness, o.bore_diameter,
                                                     o.design_name, step);
  } else {
    igs.add(r.track, "CAM TRACK");
    stp.add(r.track, "cam track centre line");
    x3d.add(r.track, "track");
    DxfWriter dxf(DxfOptions{std::max(10, r.track.degree()), 1e-6});
    dxf.add(r.track, "TRACK");
    content[stem + ".dxf"] = dxf.str();
    if (!r.groove.empty()) {
      IgesWriter groove_igs;
      StepWriter groove_stp(o.design_name);
      for (const GrooveSurface& g : r.groove) {
        groove_igs.add(g.surface, g.side > 0 ? "GROOVE WALL UPPER" : "GROOVE WALL LOWER");
        groove_stp.add(g.surface, g.side > 0 ? "groove wall +z" : "groove wall -z");
      }
      IgesHeader gi = iges;
      StepHeader gs = step;
      gi.file_name = "groove.igs";
      gs.file_name = "groove.stp";
      content["groove.igs"] = groove_igs.str(gi);
      content["groove.stp"] = groove_stp.str(gs);
    }
  }
  iges.file_name = stem + ".igs";
  step.file_name = stem + ".stp";
  content[stem + ".igs"] = igs.str(iges);
  content[stem + ".stp"] = stp.str(step);
  content[stem + ".x3d"] = x3d.str("polarform cam " + o.design_name);
  content["svaj.csv"] = svaj_csv(r);
  std::map<std::string, std::string> svgs = {{"svaj.svg", svaj_figure(r).svg()},
                                             {"analysis.svg", analysis_figure(r).svg()},
                                             {"profile.svg", profile_figure(r).svg()},
                                             {"error.svg", conversion_error_figure(r).svg()}};
  content.insert(svgs.begin(), svgs.end());
  std::vector<std::string> files;
  for (const auto& [name, text] : content) files.push_back(name);
  files.push_back("report.json");
  files.push_back("report.html");
  const json report = cam_report_json(r, files);
  content["report.json"] = report.dump(2) + "\n";
  content["report.html"] = html_report(r, o, report, svgs);

  write_files_atomically(dir, content);
  return files;
}

}  // namespace polarform
