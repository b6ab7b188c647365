#include "jobs/sweep/sweep_outputs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "export/atomic_file.h"
#include "export/colormap.h"
#include "export/dxf_writer.h"
#include "export/html_report.h"
#include "export/iges_writer.h"
#include "export/ply_writer.h"
#include "export/step_solid.h"
#include "export/step_writer.h"
#include "export/svg_plot.h"
#include "export/x3d_writer.h"
#include "jobs/report/deviation_ply.h"
#include "jobs/report/exchange_headers.h"
#include "jobs/report/output_files.h"
#include "jobs/sweep/sweep_plots.h"
#include "polarform_version.h"
#include "src/number_text.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(std::abs(a.normalized().dot(b.normalized())), 0.0, 1.0)) * 180 /
         std::numbers::pi;
}

std::string triple(const Eigen::Vector3d& v) {
  return "(" + format_trimmed(v.x(), 9) + ", " + format_trimmed(v.y(), 9) + ", " +
         format_trimmed(v.z(), 9) + ")";
}

std::string html_report(const SweepJobResult& r, const std::string& profile,
                        const std::string& preview, const std::vector<std::string>& files) {
  const SweptFit& v = r.fit();
  HtmlReport html("polarform sweep report: " + r.input.filename().string());
  std::vector<std::pair<std::string, std::string>> key = {
      {"kind", r.kind()}, {"points", std::to_string(r.points.cols())}};
  if (r.is_sections) {
    key.push_back({"sections", std::to_string(r.sections->stations.size())});
    key.push_back({"spine", std::string(r.sections->spine_curved ? "curved" : "straight") + ", " +
                                format_trimmed(r.sections->spine_length, 9) + " mm"});
  } else if (r.is_extrusion) {
    key.push_back({"extrusion direction", triple(r.extrusion->direction)});
    key.push_back({"extrusion length [mm]", format_trimmed(r.extrusion->length(), 9)});
  } else {
    key.push_back({"axis direction", triple(r.revolution->axis.direction)});
  }
  if (!r.is_sections)
    key.push_back({r.is_extrusion ? "section loops" : "profile loops",
                   std::to_string(v.profile.loops.size())});
  key.push_back({"error rms / p95 / max [mm]", format_trimmed(v.error.rms, 6) + " / " +
                                                   format_trimmed(v.error.p95, 6) + " / " +
                                                   format_trimmed(v.error.max, 6)});
  key.push_back({"tolerance [mm]",
                 format_trimmed(v.tolerance, 6) + (r.tolerance_met() ? " (met)" : " (NOT met)")});
  html.add_key_figures(key);
  html.add_paragraph(r.reason + ".");
  html.add_svg(profile,
               r.is_sections    ? "The sections in their station frames: the points of every slab "
                                  "and the fitted curves."
               : r.is_extrusion ? "The section: every point projected along the extrusion "
                                  "direction, the points fitted, corners and the curve."
                                : "The meridian profile: every point projected to (z, r), the "
                                  "points fitted, corners and the curve.");
  html.add_svg(preview, r.is_sections ? "Signed distance of every point from the skin against "
                                        "its arc length along the spine."
                        : r.is_extrusion
                            ? "Signed distance of every point from the extruded surface against "
                              "its angle about the section's centroid."
                            : "Signed distance of every point from the recovered surface against "
                              "z.");
  html.add_file_list(files);
  return html.html();
}

json error_json(const ErrorStats& e) {
  return {{"rms", e.rms},
          {"mean", e.mean},
          {"max", e.max},
          {"p95", e.p95},
          {"p99", e.p99},
          {"count", e.count},
          {"kind", "true distance of every input point to the surface"}};
}

json revolution_json(const RevolutionRecovery& v) {
  const Eigen::Vector3d d = v.axis.point - v.start_axis.point;
  return {{"point", vec(v.axis.point)},
          {"direction", vec(v.axis.direction)},
          {"start_direction", vec(v.start_axis.direction)},
          {"tilt_from_start_deg", angle_deg(v.axis.direction, v.start_axis.direction)},
          {"offset_from_start_mm", (d - d.dot(v.axis.direction) * v.axis.direction).norm()},
          {"rms_before_mm", v.refinement.rms_before},
          {"rms_after_mm", v.refinement.rms_after},
          {"iterations", v.refinement.iterations},
          {"refined_on", v.ring_axis ? "ring clusters" : "profile residuals"},
          {"set_aside_points", v.set_aside}};
}

json extrusion_json(const ExtrusionRecovery& x) {
  const Eigen::Matrix2d& C = x.refinement.covariance;
  return {{"direction", vec(x.direction)},
          {"length", x.length()},
          {"start_direction", vec(x.start_direction)},
          {"tilt_from_start_deg", angle_deg(x.direction, x.start_direction)},
          {"direction_sd_deg", std::sqrt(std::max(C.trace(), 0.0)) * 180 / std::numbers::pi},
          {"normals_flatness", x.normals_flatness},
          {"rms_before_mm", x.refinement.rms_before},
          {"rms_after_mm", x.refinement.rms_after},
          {"iterations", x.refinement.iterations},
          {"refined_on", "section residuals"},
          {"section_plane",
           {{"origin", vec(x.origin + x.v_low * x.direction)},
            {"x_axis", vec(x.e1)},
            {"y_axis", vec(x.e2)},
            {"note",
             "the section's (x, y) are in this plane; the surface runs from it along "
             "direction for length mm"}}}};
}

json sections_json(const SectionRecovery& x) {
  json stations = json::array();
  for (const SectionStation& s : x.stations)
    stations.push_back({{"s_mm", s.s},
                        {"centre", vec(s.centre)},
                        {"points", s.points},
                        {"mean_radius_mm", s.curve.mean_radius},
                        {"rms_mm", s.curve.error.rms},
                        {"max_mm", s.curve.error.max}});
  return {{"count", x.stations.size()},
          {"spine",
           {{"kind", x.spine_curved ? "curved" : "straight"},
            {"length_mm", x.spine_length},
            {"iterations", x.spine_iterations},
            {"start", vec(x.spine->frame(x.stations.front().s).point)},
            {"end", vec(x.spine->frame(x.stations.back().s).point)}}},
          {"slab_half_width_mm", x.slab},
          {"adaptive_rounds", x.rounds},
          {"radius_function_spans", x.spans},
          {"section_error_kind",
           "radial residual of a slab's points to its section r = F + a·G (a the offset along "
           "the spine, F the section)"},
          {"stations", stations}};
}

// The meridian profile or the extrusion's section loops.
json profile_json(const SweepJobResult& r) {
  const SweptFit& v = r.fit();
  json loops = json::array();
  for (const MeridianLoop& l : v.profile.loops) {
    json corners = json::array();
    for (const Eigen::Vector2d& c : l.corners) corners.push_back(json::array({c.x(), c.y()}));
    json ctrl = json::array();
    for (const Eigen::Vector2d& c : l.curve.control_points())
      ctrl.push_back(json::array({c.x(), c.y()}));
    loops.push_back({{"closed", l.closed},
                     {"points_fitted", l.points.cols()},
                     {"corners", corners},
                     {"ends_on_axis", json::array({l.start_on_axis, l.end_on_axis})},
                     {"degree", l.curve.degree()},
                     {"knots", l.curve.knots()},
                     {"control_points", ctrl},
                     {"fit_max_mm", l.fit_max}});
  }
  return {{"source", v.profile.rings ? "ring clusters" : "MLS-thinned scan"},
          {"plane", r.is_extrusion ? "section: x along extrusion.section_plane.x_axis, y along "
                                     "its y_axis, from its origin [mm]"
                                   : "z along the axis from axis.point, r from the axis [mm]"},
          {"loops", loops}};
}

// An extrusion of exactly one closed section loop bounds a solid.
bool has_solid(const SweepJobResult& r) {
  return r.is_extrusion && r.extrusion->profile.loops.size() == 1 &&
         r.extrusion->profile.loops[0].closed;
}

}  // namespace

json sweep_report_json(const SweepJobResult& r, const std::vector<std::string>& files) {
  const SweptFit& v = r.fit();
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "sweep";
  j["input"] = {{"file", r.input.string()}, {"points", r.points.cols()}, {"dropped", r.dropped}};
  j["kind"] = r.kind();
  j["reason"] = r.reason;
  if (r.evidence)
    j["evidence"] = {{"normals_flatness", r.evidence->normals_flatness},
                     {"extrusion_like", r.evidence->extrusion_like()},
                     {"median_azimuthal_normal", r.evidence->azimuthal_normal},
                     {"revolution_like", r.evidence->revolution_like()},
                     {"pca_tie_ratio", r.evidence->tie_ratio}};
  if (r.revolution) {
    const RevolutionRecovery& rv = *r.revolution;
    j["pca"] = {{"eigenvalues", vec(rv.pca.eigenvalues)},
                {"axes", json::array({vec(rv.pca.axes.col(0)), vec(rv.pca.axes.col(1)),
                                      vec(rv.pca.axes.col(2))})},
                {"box_centre", vec(rv.pca.box_centre)},
                {"box_extent", vec(rv.pca.box_high - rv.pca.box_low)},
                {"tie_ratio", rv.tie_ratio}};
  }
  if (r.revolution && !r.is_extrusion) j["axis"] = revolution_json(*r.revolution);
  if (r.is_extrusion) j["extrusion"] = extrusion_json(*r.extrusion);
  if (r.is_sections) j["sections"] = sections_json(*r.sections);
  if (r.revolution && r.extrusion) {
    const SweptFit& other = r.is_extrusion ? static_cast<const SweptFit&>(*r.revolution)
                                           : static_cast<const SweptFit&>(*r.extrusion);
    j["alternative"] = {{"kind", r.is_extrusion ? "revolution" : "extrusion"},
                        {"error_mm", error_json(other.error)}};
  }
  if (!r.is_sections) j["profile"] = profile_json(r);
  json degrees = json::array();
  for (const NurbsSurface& s : v.surfaces)
    degrees.push_back(json::array({s.degree_u(), s.degree_v()}));
  j["surface"] = {
      {"count", v.surfaces.size()},
      {"degrees", degrees},
      {"kind", r.is_sections    ? "sections skinned along the spine (NURBS Book §10.3; u the "
                                  "section angle from the station frame's x, v the arc length)"
               : r.is_extrusion ? "section extruded along the direction (degree (p, 1))"
                                : "profile × rational quadratic circle (NURBS Book A8.1)"}};
  j["error_mm"] = error_json(v.error);
  j["tolerance_mm"] = v.tolerance;
  j["tolerance_met"] = r.tolerance_met();
  j["unexplained_points"] = v.unexplained;
  if (r.is_sections) {
    const SectionRecovery::Timings& t = r.sections->timings_s;
    j["timings_s"] = {{"read", r.read_seconds},  {"frame", t.frame}, {"slicing", t.slicing},
                      {"sections", t.sections},  {"skin", t.skin},   {"error", t.error},
                      {"total", r.total_seconds}};
  } else if (r.is_extrusion) {
    const ExtrusionRecovery::Timings& t = r.extrusion->timings_s;
    j["timings_s"] = {{"read", r.read_seconds},  {"frame", t.frame},     {"direction", t.direction},
                      {"profile", t.profile},    {"surface", t.surface}, {"error", t.error},
                      {"total", r.total_seconds}};
  } else {
    const RevolutionRecovery::Timings& t = r.revolution->timings_s;
    j["timings_s"] = {{"read", r.read_seconds},  {"frame", t.frame},     {"axis", t.axis},
                      {"profile", t.profile},    {"surface", t.surface}, {"error", t.error},
                      {"total", r.total_seconds}};
  }
  if (r.interrogation) j["interrogation"] = surface_interrogation_json(*r.interrogation);
  j["files"] = files;
  return j;
}

std::vector<std::string> write_sweep_outputs(const SweepJobResult& r,
                                             const std::filesystem::path& dir) {
  const SweptFit& v = r.fit();
  std::map<std::string, std::string> content;
  const std::string title = "polarform sweep of " + r.input.filename().string();
  auto [iges, step] = exchange_headers(title);
  IgesWriter igs, profile_igs;
  StepWriter stp(r.input.stem().string()), profile_stp(r.input.stem().string() + " profile");
  X3dWriter x3d;
  DxfWriter dxf;
  const std::string surface_name = r.is_sections    ? "SKIN "
                                   : r.is_extrusion ? "EXTRUSION "
                                                    : "REVOLUTION ";
  for (std::size_t l = 0; l < v.surfaces.size(); ++l) {
    const std::string name = surface_name + std::to_string(l + 1);
    igs.add(v.surfaces[l], name);
    stp.add(v.surfaces[l], (r.is_sections    ? "skinned surface "
                            : r.is_extrusion ? "extruded surface "
                                             : "surface of revolution ") +
                               std::to_string(l + 1));
    x3d.add(v.surfaces[l], name);
    if (r.is_sections) continue;
    profile_igs.add(v.profile.loops[l].curve, "PROFILE " + std::to_string(l + 1));
    profile_stp.add(v.profile.loops[l].curve, "profile " + std::to_string(l + 1));
    dxf.add(v.profile.loops[l].curve, "PROFILE");
  }
  iges.file_name = "surface.igs";
  content["surface.igs"] = igs.str(iges);
  step.file_name = "surface.stp";
  content["surface.stp"] = stp.str(step);
  if (r.is_sections) {
    IgesWriter sections_igs;
    for (std::size_t k = 0; k < r.sections->stations.size(); ++k)
      sections_igs.add(r.sections->stations[k].placed, "SECTION " + std::to_string(k + 1));
    iges.file_name = "sections.igs";
    content["sections.igs"] = sections_igs.str(iges);
  } else {
    iges.file_name = "profile.igs";
    content["profile.igs"] = profile_igs.str(iges);
    step.file_name = "profile.stp";
    content["profile.stp"] = profile_stp.str(step);
    content["profile.dxf"] = dxf.str();
  }
  if (has_solid(r)) {
    const ExtrusionRecovery& x = *r.extrusion;
    Eigen::Isometry3d placement = Eigen::Isometry3d::Identity();
    placement.linear().col(0) = x.e1;
    placement.linear().col(1) = x.e2;
    placement.linear().col(2) = x.direction;
    placement.translation() = x.origin + x.v_low * x.direction;
    step.file_name = "solid.stp";
    content["solid.stp"] = step_extruded_solid(x.profile.loops[0].curve, x.length(), std::nullopt,
                                               r.input.stem().string(), step, placement);
  }
  content["surface.x3d"] = x3d.str(title);
  const std::string profile_svg = svg_document(sweep_profile_figure(r));
  const std::string preview_svg = svg_document(sweep_preview_figure(r));
  content[r.is_sections ? "sections.svg" : "profile.svg"] = profile_svg;
  content["preview.svg"] = preview_svg;
  std::vector<std::string> files;
  for (const auto& [file, text] : content) files.push_back(file);
  files.insert(files.end(), {"deviation.ply", "report.html", "report.json"});
  if (r.interrogation)
    for (const std::string& f : interrogation_file_names()) files.push_back(f);
  std::sort(files.begin(), files.end());
  content["report.html"] = html_report(r, profile_svg, preview_svg, files);
  content["report.json"] = report_json_text(sweep_report_json(r, files));
  OutputTransaction outputs(dir);  // all or nothing
  for (const auto& [name, text] : content) outputs.add(name, text);
  add_deviation_ply(outputs, dir, r.points, v.distances, v.error.p99);
  if (r.interrogation) add_interrogation_files(outputs, dir, *r.interrogation, title);
  outputs.commit();
  return files;
}

}  // namespace polarform
