#include "jobs/cam/cam_outputs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "export/atomic_file.h"
#include "export/csv_writer.h"
#include "export/dxf_writer.h"
#include "export/html_report.h"
#include "export/iges_writer.h"
#include "export/step_grooved_plate.h"
#include "export/step_solid.h"
#include "export/step_writer.h"
#include "export/svg_plot.h"
#include "export/x3d_writer.h"
#include "jobs/cam/cam_key_figures.h"
#include "jobs/cam/cam_plots.h"
#include "jobs/cam/cam_report.h"
#include "jobs/report/conversion_report.h"
#include "jobs/report/exchange_headers.h"
#include "jobs/report/output_files.h"
#include "polarform_version.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

// s in mm, or in degrees of arm swing for an oscillating follower.
std::string svaj_csv(const CamDesignStage& design, const CamAnalysisStage& analysis) {
  const std::string u(motion_unit(design.project.cam.follower.kind));
  std::vector<std::string> headers = {"cam angle theta [deg]",
                                      "s [" + u + "]",
                                      "v [" + u + "/s]",
                                      "a [" + u + "/s^2]",
                                      "j [" + u + "/s^3]",
                                      "ds/dtheta [" + u + "/rad]",
                                      "d2s/dtheta2 [" + u + "/rad^2]",
                                      "d3s/dtheta3 [" + u + "/rad^3]"};
  const auto* plate = std::get_if<PlateCamAnalysis>(&analysis.cam);
  const auto* cylindrical = std::get_if<CylindricalCamAnalysis>(&analysis.cam);
  if (plate)
    for (const char* h : {"pressure angle [deg]", "contour radius of curvature [mm]",
                          "pitch radius of curvature [mm]"})
      headers.push_back(h);
  else
    headers.push_back("pressure angle at pitch radius [deg]");
  CsvWriter csv(headers);
  const std::vector<double>& angles = analysis.angles;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    double d[4];
    design.program.derivatives(angles[i], 3, d);
    const Kinematics& k = analysis.kinematics[i];
    std::vector<double> row = {angles[i] * kDegreesPerRadian,
                               k.displacement,
                               k.velocity,
                               k.acceleration,
                               k.jerk,
                               d[1],
                               d[2],
                               d[3]};
    if (plate) {
      const CamSample& s = plate->analysis.samples[i];
      row.push_back(s.pressure_angle * kDegreesPerRadian);
      row.push_back(1 / s.contour_curvature);
      row.push_back(1 / s.pitch_curvature);
    } else {
      row.push_back(cylindrical->pressure_angle[i] * kDegreesPerRadian);
    }
    csv.row(row);
  }
  return csv.str();
}

// A grooved cam's flanks (groove_plate.*, with --solid the groove plate as cam_solid.stp) or a
// conjugate cam's second contour (conjugate.*, with --solid conjugate_solid.stp).
void add_companion_files(const CamJobResult& r, const CompanionCurve& companion,
                         const CamOutputOptions& o, IgesHeader iges, StepHeader step,
                         std::map<std::string, std::string>& content) {
  const NurbsCurve2d& profile = std::get<PlateProfile>(r.conversion.profile).exported();
  const NurbsCurve2d& second = companion.exported();
  const bool groove = companion.kind == CompanionKind::GrooveOuterFlank;
  const std::string stem = groove ? "groove_plate" : "conjugate";
  IgesWriter igs;
  StepWriter stp(o.design_name);
  DxfWriter dxf(DxfOptions{std::max({10, profile.degree(), second.degree()}), 1e-6});
  if (groove) {
    igs.add(profile, "GROOVE INNER FLANK");
    stp.add(profile, "groove inner flank");
    dxf.add(profile, "GROOVE_INNER");
    igs.add(second, "GROOVE OUTER FLANK");
    stp.add(second, "groove outer flank");
    dxf.add(second, "GROOVE_OUTER");
  } else {
    igs.add(second, "CONJUGATE CAM");
    stp.add(second, "conjugate cam contour");
    dxf.add(second, "CONJUGATE");
  }
  iges.file_name = stem + ".igs";
  step.file_name = stem + ".stp";
  content[stem + ".igs"] = igs.str(iges);
  content[stem + ".stp"] = stp.str(step);
  content[stem + ".dxf"] = dxf.str();
  if (!o.solid_thickness) return;
  const CamDesign& d = r.project().cam;
  step.file_name = groove ? "cam_solid.stp" : "conjugate_solid.stp";
  content[step.file_name] =
      groove
          ? step_grooved_plate_solid({profile, second, d.follower.roller_radius, *o.solid_thickness,
                                      d.groove_depth, o.bore_diameter},
                                     o.design_name, step)
          : step_extruded_solid(second, *o.solid_thickness, o.bore_diameter, o.design_name, step);
}

std::vector<std::pair<std::string, std::string>> pairs(const std::vector<KeyFigure>& figures) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const KeyFigure& f : figures) out.emplace_back(f.name, f.value);
  return out;
}

// What a report opens with (jobs/cam/cam_key_figures.h): the design, the key results (with
// `extra` rows), the warnings and the motion program's continuity issues.
void add_design_and_results(HtmlReport& html, const CamDesignStage& design,
                            const CamAnalysisStage& analysis, const CamConversionStage* conversion,
                            std::vector<std::pair<std::string, std::string>> extra = {}) {
  html.add_heading("Design");
  html.add_key_figures(pairs(cam_design_inputs(design)));
  html.add_heading("Key results");
  std::vector<std::pair<std::string, std::string>> key =
      pairs(cam_key_results(design, analysis, conversion));
  key.insert(key.end(), extra.begin(), extra.end());
  html.add_key_figures(key);
  for (const std::string& w : analysis.warnings) html.add_paragraph("Warning: " + w);
  if (conversion)
    for (const std::string& w : conversion->warnings) html.add_paragraph("Warning: " + w);
  if (!design.continuity.empty()) {
    html.add_heading("Continuity of the motion program");
    for (const ContinuityIssue& issue : design.continuity) html.add_paragraph(issue.message());
  }
}

std::string html_report(const CamJobResult& r, const CamOutputOptions& o, const json& report,
                        const std::map<std::string, std::string>& svgs) {
  HtmlReport html("polarform cam report: " + o.design_name);
  const PolarConversion& c = r.conversion.conversion;
  const bool plate = r.plate();
  // First what was asked and what came of it, then the details.
  add_design_and_results(html, r.design, r.analysis, &r.conversion,
                         {{"max tangent jump at arc junctions",
                           format_trimmed(c.max_tangent_jump * kDegreesPerRadian, 6) + "°"}});
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
  html.add_table({"arc start ψ [deg]", "sweep [deg]", "max radial error [µm]"}, arcs);
  html.add_paragraph("Error budget: law → B-spline " +
                     (c.function_exact ? std::string("exact") : format_trimmed(c.function_error * 1e3, 4) + " µm") +
                     ", base-circle synchronization " + format_trimmed(c.synchronization_error * 1e3, 4) + " µm.");
  const auto* track = std::get_if<CylindricalTrack>(&r.conversion.profile);
  if (track && !track->groove.empty()) {
    html.add_heading("Groove walls");
    std::vector<std::vector<std::string>> walls;
    for (const GrooveSurface& w : track->groove)
      walls.push_back(
          {w.side > 0 ? "+z" : "−z",
           std::to_string(w.surface.degree_u()) + " x " + std::to_string(w.surface.degree_v()),
           std::to_string(w.surface.size_u()) + " x " + std::to_string(w.surface.size_v()),
           format_trimmed(w.max_error * 1e3, 4)});
    html.add_table({"wall", "degrees (u x ρ)", "control net", "measured max error [µm]"}, walls);
    html.add_paragraph(
        "groove.igs and groove.stp hold both walls as rational tensor-product "
        "surfaces (ρ·X, ρ·Y, Z): x, y exact on the cylinders of radius ρ from " +
        format_trimmed(track->groove.front().surface.front_v(), 6) + " to " +
        format_trimmed(track->groove.front().surface.back_v(), 6) +
        " mm, the height Z fitted to the exact roller envelope; the error is the "
        "largest height gap at equal polar angle and radius, measured densely.");
  }
  if (const auto& second = r.conversion.companion) {
    const PolarConversion& k = second->conversion;
    const bool groove = second->kind == CompanionKind::GrooveOuterFlank;
    html.add_heading(groove ? "Groove outer flank" : "Conjugate (second) cam");
    html.add_paragraph(
        std::string(groove
                        ? "The groove's outer flank, pitch curve + roller radius along its normal "
                          "(the profile is the inner flank; both in groove_plate.igs/.stp/.dxf)"
                        : "The second cam's contour, driving the follower's second roller "
                          "(conjugate.igs/.stp/.dxf)") +
        ": degree " + std::to_string(k.curve.degree()) + ", " + std::to_string(k.curve.size()) +
        " control points, " + std::to_string(k.arcs.size()) + " arcs, measured max radial error " +
        format_trimmed(to_micrometres(k.max_radial_error), 4) + " µm, max normal error " +
        format_trimmed(to_micrometres(k.max_normal_error), 4) + " µm.");
  }
  const auto* profile = std::get_if<PlateProfile>(&r.conversion.profile);
  if (profile && profile->limited) {
    const LimitedCurve& l = *profile->limited;
    html.add_paragraph("Degree-" + std::to_string(l.curve.degree()) +
                       " profile (profile_deg3.dxf): " + std::to_string(l.control_points) +
                       " control points, measured max radial error " +
                       format_trimmed(to_micrometres(l.max_radial_error), 4) + " µm.");
  }
  html.add_file_list(report["files"].get<std::vector<std::string>>());
  return html.html();
}

// The report of an infeasible design: what was asked, what the analyses found, why no profile
// could be made, and the plots that show where.
std::string infeasible_html_report(const InfeasibleCam& cam, const CamOutputOptions& o,
                                   const json& report,
                                   const std::map<std::string, std::string>& svgs) {
  HtmlReport html("polarform cam report: " + o.design_name + " (INFEASIBLE)");
  html.add_heading("INFEASIBLE design: no profile was written");
  html.add_paragraph(cam.reason);
  html.add_paragraph(
      "The contour undercuts where analysis.svg shades the cam angles in its radius-of-curvature "
      "panel: there the cutter would remove material the contour needs. Increase the base "
      "radius, lengthen the segment or choose a softer law there.");
  add_design_and_results(html, cam.design, cam.analysis, nullptr);
  html.add_heading("Motion and analyses");
  html.add_svg(svgs.at("analysis.svg"),
               "Pressure angle and radii of curvature; the undercut ranges shaded.");
  html.add_svg(svgs.at("svaj.svg"),
               "Displacement, velocity, acceleration and jerk against cam angle.");
  html.add_file_list(report["files"].get<std::vector<std::string>>());
  return html.html();
}

}  // namespace

std::map<std::string, std::string> render_cam_outputs(const CamJobResult& r,
                                                      const CamOutputOptions& o) {
  const bool plate = r.plate();
  if (o.solid_thickness && !plate) throw InputError("--solid applies to plate cams only");
  std::map<std::string, std::string> content;
  const std::string stem = plate ? "profile" : "track";
  auto [iges, step] = exchange_headers("cam " + o.design_name);
  IgesWriter igs;
  StepWriter stp(o.design_name);
  X3dWriter x3d;
  if (const auto* profile = std::get_if<PlateProfile>(&r.conversion.profile)) {
    const NurbsCurve2d& curve = profile->exported();
    igs.add(curve, "CAM PROFILE");
    stp.add(curve, "cam profile");
    x3d.add(curve, "profile");
    DxfWriter dxf(DxfOptions{std::max(10, curve.degree()), 1e-6});
    dxf.add(curve, "PROFILE");
    dxf.add_circle(Eigen::Vector3d::Zero(), r.project().cam.base_radius, "BASE_CIRCLE");
    content[stem + ".dxf"] = dxf.str();
    if (profile->limited) {
      DxfWriter limited;
      limited.add(profile->limited->curve, "PROFILE");
      limited.add_circle(Eigen::Vector3d::Zero(), r.project().cam.base_radius, "BASE_CIRCLE");
      content["profile_deg" + std::to_string(profile->limited->curve.degree()) + ".dxf"] =
          limited.str();
    }
    const auto& companion = r.conversion.companion;
    if (companion) add_companion_files(r, *companion, o, iges, step, content);
    if (o.solid_thickness && !(companion && companion->kind == CompanionKind::GrooveOuterFlank))
      content["cam_solid.stp"] = step_extruded_solid(curve, *o.solid_thickness, o.bore_diameter,
                                                     o.design_name, step);
  } else {
    const CylindricalTrack& track = std::get<CylindricalTrack>(r.conversion.profile);
    igs.add(track.curve, "CAM TRACK");
    stp.add(track.curve, "cam track centre line");
    x3d.add(track.curve, "track");
    DxfWriter dxf(DxfOptions{std::max(10, track.curve.degree()), 1e-6});
    dxf.add(track.curve, "TRACK");
    content[stem + ".dxf"] = dxf.str();
    if (!track.groove.empty()) {
      IgesWriter groove_igs;
      StepWriter groove_stp(o.design_name);
      for (const GrooveSurface& g : track.groove) {
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
  content["svaj.csv"] = svaj_csv(r.design, r.analysis);
  const std::map<std::string, std::string> svgs = {
      {"svaj.svg", svg_document(svaj_figure(r.design, r.analysis))},
      {"analysis.svg", svg_document(analysis_figure(r.design, r.analysis))},
      {"profile.svg", svg_document(profile_figure(r.design, r.analysis, r.conversion))},
      {"error.svg", svg_document(conversion_error_figure(r.conversion))}};
  content.insert(svgs.begin(), svgs.end());
  if (r.analysis.dynamics) {
    content["force.svg"] = svg_document(contact_force_figure(r.design, r.analysis));
    content["torque.svg"] = svg_document(camshaft_torque_figure(r.design, r.analysis));
    content["stress.svg"] = svg_document(contact_stress_figure(r.design, r.analysis));
  }
  const std::vector<std::string> files = report_file_list(content);
  const json report = cam_report_json(r, files);
  content["report.json"] = report_json_text(report);
  content["report.html"] = html_report(r, o, report, svgs);
  return content;
}

std::vector<std::string> write_cam_outputs(const CamJobResult& r, const std::filesystem::path& dir,
                                           const CamOutputOptions& o) {
  // Everything is rendered in memory first, so a failure writes nothing.
  const std::map<std::string, std::string> content = render_cam_outputs(r, o);
  write_files_atomically(dir, content);
  return report_file_list(content);
}

std::map<std::string, std::string> render_infeasible_cam_outputs(const InfeasibleCam& cam,
                                                                 const CamOutputOptions& o) {
  std::map<std::string, std::string> content;
  content["svaj.csv"] = svaj_csv(cam.design, cam.analysis);
  const std::map<std::string, std::string> svgs = {
      {"svaj.svg", svg_document(svaj_figure(cam.design, cam.analysis))},
      {"analysis.svg", svg_document(analysis_figure(cam.design, cam.analysis))}};
  content.insert(svgs.begin(), svgs.end());
  const std::vector<std::string> files = report_file_list(content);
  const json report = cam_infeasible_report_json(cam, files);
  content["report.json"] = report_json_text(report);
  content["report.html"] = infeasible_html_report(cam, o, report, svgs);
  return content;
}

std::filesystem::path infeasible_outputs_dir(const std::filesystem::path& out) {
  std::error_code ec;
  const bool fresh = !std::filesystem::exists(out, ec) ||
                     (std::filesystem::is_directory(out, ec) && std::filesystem::is_empty(out, ec));
  if (fresh) return out;
  std::filesystem::path sibling = out;
  if (!sibling.has_filename()) sibling = sibling.parent_path();  // "out/" -> "out"
  sibling += ".infeasible";
  return sibling;
}

std::vector<std::string> write_infeasible_cam_outputs(const InfeasibleCam& cam,
                                                      const std::filesystem::path& dir,
                                                      const CamOutputOptions& o) {
  const std::map<std::string, std::string> content = render_infeasible_cam_outputs(cam, o);
  write_files_atomically(dir, content);
  return report_file_list(content);
}

}  // namespace polarform
