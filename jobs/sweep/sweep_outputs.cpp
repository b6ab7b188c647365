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

std::string html_report(const SweepJobResult& r, const std::string& profile,
                        const std::string& preview, const std::vector<std::string>& files) {
  const RevolutionRecovery& v = r.revolution;
  HtmlReport html("polarform sweep report: " + r.input.filename().string());
  html.add_key_figures({{"kind", r.kind},
                        {"points", std::to_string(r.points.cols())},
                        {"axis direction", "(" + format_trimmed(v.axis.direction.x(), 9) + ", " +
                                               format_trimmed(v.axis.direction.y(), 9) + ", " +
                                               format_trimmed(v.axis.direction.z(), 9) + ")"},
                        {"profile loops", std::to_string(v.profile.loops.size())},
                        {"error rms / p95 / max [mm]", format_trimmed(v.error.rms, 6) + " / " +
                                                           format_trimmed(v.error.p95, 6) + " / " +
                                                           format_trimmed(v.error.max, 6)},
                        {"tolerance [mm]", format_trimmed(v.tolerance, 6) +
                                               (r.tolerance_met() ? " (met)" : " (NOT met)")}});
  html.add_paragraph(r.reason + ".");
  html.add_svg(profile,
               "The meridian profile: every point projected to (z, r), the points fitted, corners "
               "and the curve.");
  html.add_svg(preview, "Signed distance of every point from the recovered surface against z.");
  html.add_file_list(files);
  return html.html();
}

}  // namespace

json sweep_report_json(const SweepJobResult& r, const std::vector<std::string>& files) {
  const RevolutionRecovery& v = r.revolution;
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "sweep";
  j["input"] = {{"file", r.input.string()}, {"points", r.points.cols()}, {"dropped", r.dropped}};
  j["kind"] = r.kind;
  j["reason"] = r.reason;
  j["pca"] = {{"eigenvalues", vec(v.pca.eigenvalues)},
              {"axes", json::array({vec(v.pca.axes.col(0)), vec(v.pca.axes.col(1)),
                                    vec(v.pca.axes.col(2))})},
              {"box_centre", vec(v.pca.box_centre)},
              {"box_extent", vec(v.pca.box_high - v.pca.box_low)},
              {"tie_ratio", v.tie_ratio}};
  const Eigen::Vector3d d = v.axis.point - v.start_axis.point;
  j["axis"] = {{"point", vec(v.axis.point)},
               {"direction", vec(v.axis.direction)},
               {"start_direction", vec(v.start_axis.direction)},
               {"tilt_from_start_deg", angle_deg(v.axis.direction, v.start_axis.direction)},
               {"offset_from_start_mm", (d - d.dot(v.axis.direction) * v.axis.direction).norm()},
               {"rms_before_mm", v.refinement.rms_before},
               {"rms_after_mm", v.refinement.rms_after},
               {"iterations", v.refinement.iterations},
               {"refined_on", v.ring_axis ? "ring clusters" : "profile residuals"}};
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
  j["profile"] = {{"source", v.profile.rings ? "ring clusters" : "MLS-thinned scan"},
                  {"plane", "z along the axis from axis.point, r from the axis [mm]"},
                  {"loops", loops}};
  json degrees = json::array();
  for (const NurbsSurface& s : v.surfaces)
    degrees.push_back(json::array({s.degree_u(), s.degree_v()}));
  j["surface"] = {{"count", v.surfaces.size()},
                  {"degrees", degrees},
                  {"kind", "profile × rational quadratic circle (NURBS Book A8.1)"}};
  const ErrorStats& e = v.error;
  j["error_mm"] = {{"rms", e.rms},
                   {"mean", e.mean},
                   {"max", e.max},
                   {"p95", e.p95},
                   {"p99", e.p99},
                   {"count", e.count},
                   {"kind", "true distance of every input point to the surface"}};
  j["tolerance_mm"] = v.tolerance;
  j["tolerance_met"] = r.tolerance_met();
  j["unexplained_points"] = v.unexplained;
  j["timings_s"] = {{"read", r.read_seconds},         {"frame", v.timings_s.frame},
                    {"axis", v.timings_s.axis},       {"profile", v.timings_s.profile},
                    {"surface", v.timings_s.surface}, {"error", v.timings_s.error},
                    {"total", r.total_seconds}};
  if (r.interrogation) j["interrogation"] = surface_interrogation_json(*r.interrogation);
  j["files"] = files;
  return j;
}

std::vector<std::string> write_sweep_outputs(const SweepJobResult& r,
                                             const std::filesystem::path& dir) {
  const RevolutionRecovery& v = r.revolution;
  std::map<std::string, std::string> content;
  const std::string title = "polarform sweep of " + r.input.filename().string();
  auto [iges, step] = exchange_headers(title);
  IgesWriter igs, profile_igs;
  StepWriter stp(r.input.stem().string());
  X3dWriter x3d;
  DxfWriter dxf;
  for (std::size_t l = 0; l < v.surfaces.size(); ++l) {
    const std::string name = "REVOLUTION " + std::to_string(l + 1);
    igs.add(v.surfaces[l], name);
    stp.add(v.surfaces[l], "surface of revolution " + std::to_string(l + 1));
    x3d.add(v.surfaces[l], name);
    profile_igs.add(v.profile.loops[l].curve, "PROFILE " + std::to_string(l + 1));
    dxf.add(v.profile.loops[l].curve, "PROFILE");
  }
  iges.file_name = "surface.igs";
  content["surface.igs"] = igs.str(iges);
  iges.file_name = "profile.igs";
  content["profile.igs"] = profile_igs.str(iges);
  step.file_name = "surface.stp";
  content["surface.stp"] = stp.str(step);
  content["surface.x3d"] = x3d.str(title);
  content["profile.dxf"] = dxf.str();
  const std::string profile_svg = svg_document(sweep_profile_figure(r));
  const std::string preview_svg = svg_document(sweep_preview_figure(r));
  content["profile.svg"] = profile_svg;
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
