#include "jobs/patch/patch_outputs.h"

#include <algorithm>
#include <map>

#include "export/atomic_file.h"
#include "export/colormap.h"
#include "export/csv_writer.h"
#include "export/html_report.h"
#include "export/iges_writer.h"
#include "export/ply_writer.h"
#include "export/step_writer.h"
#include "export/svg_plot.h"
#include "export/x3d_writer.h"
#include "jobs/patch/patch_plots.h"
#include "jobs/report/deviation_ply.h"
#include "jobs/report/exchange_headers.h"
#include "jobs/report/output_files.h"
#include "polarform_version.h"
#include "src/fit/point_subset.h"
#include "src/number_text.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json net(const NurbsSurface& s) { return json::array({s.size_u(), s.size_v()}); }
json degrees(const NurbsSurface& s) { return json::array({s.degree_u(), s.degree_v()}); }

std::string net_text(const NurbsSurface& s) {
  return std::to_string(s.size_u()) + " × " + std::to_string(s.size_v()) + ", degree (" +
         std::to_string(s.degree_u()) + ", " + std::to_string(s.degree_v()) + ")";
}

std::string html_report(const PatchJobResult& r, const std::string& decomposition,
                        const std::string& preview, const std::vector<std::string>& files) {
  const PatchFit& p = r.patch;
  HtmlReport html("polarform patch report: " + r.input.filename().string());
  html.add_key_figures(
      {{"points", std::to_string(r.points.cols())},
       {"boundary", r.boundary_source},
       {"base surface", base_kind_name(p.base.kind) + ", " + net_text(p.base.surface)},
       {"fitted surface", net_text(p.fit.surface)},
       {"error rms / p95 / max [mm]", format_trimmed(p.error.rms, 6) + " / " +
                                          format_trimmed(p.error.p95, 6) + " / " +
                                          format_trimmed(p.error.max, 6)},
       {"time [s]", format_trimmed(r.total_seconds, 3)}});
  html.add_paragraph(
      "Piegl & Tiller (2001): the base surface parametrises every point through its crack-free "
      "quad blanket (" +
      std::to_string(p.decomposition.blanket.quads()) + " quads at " +
      format_trimmed(p.decomposition.tolerance, 4) +
      " mm), the nearest quad found by a grid search and the parameters polished by Newton; the "
      "surface is then fitted by least squares with the boundary fixed. Distances are true "
      "point-to-surface distances of every point.");
  std::vector<std::vector<std::string>> rounds;
  for (std::size_t k = 0; k < p.fit.rounds.size(); ++k)
    rounds.push_back({std::to_string(k), format_trimmed(p.fit.rounds[k].max_distance, 6),
                      format_trimmed(p.fit.rounds[k].rms_distance, 6),
                      static_cast<int>(k) == p.fit.best_round ? "kept" : ""});
  html.add_heading("Fit rounds (parameter correction)");
  html.add_table({"round", "max [mm]", "rms [mm]", ""}, rounds);
  html.add_svg(decomposition,
               "The quad blanket of the base surface: its parameter lines and the "
               "blanket with the points seen along the maximum-area normal.");
  html.add_svg(preview, "Signed distance of every point from the fitted surface.");
  html.add_file_list(files);
  return html.html();
}

}  // namespace

json patch_report_json(const PatchJobResult& r, const std::vector<std::string>& files) {
  const PatchFit& p = r.patch;
  const FittedBoundary& b = r.boundary;
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "patch";
  j["input"] = {{"file", r.input.string()}, {"points", r.points.cols()}, {"dropped", r.dropped}};
  json curves = json::array();
  const NurbsCurve3d* fitted[4] = {&b.boundary.u0, &b.boundary.v1, &b.boundary.u1, &b.boundary.v0};
  for (std::size_t k = 0; k < 4; ++k)
    curves.push_back({{"reversed", b.reversed[k]},
                      {"corner_gap_mm", b.corner_gap[k]},
                      {"noise_mm", b.noise[k]},
                      {"control_points", fitted[k]->size()},
                      {"degree", fitted[k]->degree()},
                      {"max_distance_mm", b.max_distance[k]}});
  j["boundary"] = {{"source", r.boundary_source},
                   {"tolerance_mm", b.tolerance},
                   {"corner_tolerance_mm", b.corner_tolerance},
                   {"curves", curves}};
  j["base"] = {
      {"kind", base_kind_name(p.base.kind)},
      {"share", p.base.kind == BaseKind::bilinear ? 0.0
                                                  : static_cast<double>(p.base.fitted_points) /
                                                        static_cast<double>(r.points.cols())},
      {"fitted_points", p.base.fitted_points},
      {"control_net", net(p.base.surface)},
      {"degrees", degrees(p.base.surface)},
      {"max_distance_mm", p.base.max_distance},
      {"rms_distance_mm", p.base.rms_distance}};
  if (p.base.kind == BaseKind::bicubic)
    j["base"]["cross_scale"] = {{"kept", p.base.cross_scaled ? "scaled" : "unscaled"},
                                {"unscaled_max_distance_mm", p.base.unscaled_max_distance},
                                {"scaled_max_distance_mm", p.base.scaled_max_distance},
                                {"twist_mismatch_mm", p.base.twist_mismatch}};
  const SurfaceBlanket& bl = p.decomposition.blanket;
  j["decomposition"] = {{"tolerance_mm", p.decomposition.tolerance},
                        {"u_params", bl.u.size()},
                        {"v_params", bl.v.size()},
                        {"quads", bl.quads()},
                        {"vertices", bl.points.cols()},
                        {"flatness_tests", p.decomposition.flatness_tests}};
  j["plane"] = {
      {"normal", vec(p.plane.normal)},
      {"eigen_normal", vec(p.plane.eigen_normal)},
      {"angle_between_deg", p.plane.angle_between_deg},
      {"lsq_normal", vec(p.plane.lsq_normal)},
      {"projected_to_true_area", p.plane.area > 0 ? p.plane.projected_area / p.plane.area : 0.0},
      {"folded_triangles", p.plane.folded_triangles}};
  const PatchSearchStats& s = p.parameters.stats;
  j["search"] = {{"cells", s.cells},
                 {"point_quad_tests", s.point_quad_tests},
                 {"brute_force_tests", s.brute_force_tests},
                 {"clamped_points", s.clamped_points},
                 {"polished", s.polished}};
  if (p.thinning)
    j["thinning"] = {{"tolerance_mm", p.thinning->tolerance},
                     {"vertices", p.thinning->vertices},
                     {"kept", p.thinning->kept.size()},
                     {"mean_rings", p.thinning->mean_rings}};
  json rounds = json::array();
  for (const SurfaceFitRound& k : p.fit.rounds)
    rounds.push_back({{"max_mm", k.max_distance}, {"rms_mm", k.rms_distance}});
  if (p.net) {
    json candidates = json::array();
    for (const SurfaceNetCandidate& c : p.net->candidates)
      candidates.push_back({{"control_net", json::array({c.control_u, c.control_v})},
                            {"free_points", c.free_points},
                            {"rms_mm", c.rms},
                            {"gcv", c.gcv}});
    j["net_selection"] = {{"rule",
                           "GCV over nets grown from the boundary's; at most one free control "
                           "point per 4 points"},
                          {"samples", p.net->samples},
                          {"chosen", json::array({p.net->control_u, p.net->control_v})},
                          {"noise_mm", p.net->noise},
                          {"noise_reached", p.net->noise_reached},
                          {"stop", p.net->stop},
                          {"candidates", candidates}};
  }
  j["fit"] = {{"degrees", degrees(p.fit.surface)},       {"control_net", net(p.fit.surface)},
              {"fitted_points", p.fit.distances.size()}, {"rounds", rounds},
              {"best_round", p.fit.best_round},          {"tolerance_met", p.fit.tolerance_met}};
  const ErrorStats& e = p.error;
  j["error_mm"] = {{"rms", e.rms},
                   {"mean", e.mean},
                   {"max", e.max},
                   {"p95", e.p95},
                   {"p99", e.p99},
                   {"count", e.count},
                   {"kind", "true distance of every input point to the fitted surface"}};
  const PatchStageTimes& t = p.timings_s;
  j["timings_s"] = {{"read", r.read_seconds},
                    {"boundary", r.boundary_seconds},
                    {"base", t.base},
                    {"decomposition", t.decomposition},
                    {"search", t.search},
                    {"thinning", t.thinning},
                    {"fit", t.fit},
                    {"error", t.error},
                    {"total", r.total_seconds}};
  if (r.interrogation) j["interrogation"] = surface_interrogation_json(*r.interrogation);
  j["files"] = files;
  return j;
}

std::vector<std::string> write_patch_outputs(const PatchJobResult& r,
                                             const std::filesystem::path& dir) {
  const PatchFit& p = r.patch;
  std::map<std::string, std::string> content;
  const std::string title = "polarform patch of " + r.input.filename().string();
  auto [iges, step] = exchange_headers(title);
  IgesWriter surface_igs, base_igs;
  surface_igs.add(p.fit.surface, "PATCH");
  base_igs.add(p.base.surface, "BASE");
  iges.file_name = "surface.igs";
  content["surface.igs"] = surface_igs.str(iges);
  iges.file_name = "base.igs";
  content["base.igs"] = base_igs.str(iges);
  StepWriter stp(r.input.stem().string());
  stp.add(p.fit.surface, "fitted patch");
  step.file_name = "surface.stp";
  content["surface.stp"] = stp.str(step);
  X3dWriter x3d, base_x3d;
  x3d.add(p.fit.surface, "PATCH");
  base_x3d.add(p.base.surface, "BASE");
  content["surface.x3d"] = x3d.str(title);
  content["base.x3d"] = base_x3d.str("base surface of " + r.input.filename().string());
  CsvWriter csv({"index", "u", "v", "base distance [mm]", "clamped", "signed distance [mm]"});
  for (Eigen::Index k = 0; k < r.points.cols(); ++k)
    csv.row({static_cast<double>(k), p.parameters.u[k], p.parameters.v[k], p.parameters.distance[k],
             p.parameters.clamped[static_cast<std::size_t>(k)] ? 1.0 : 0.0, p.distances[k]});
  content["parameters.csv"] = csv.str();
  const std::string decomposition_svg = svg_document(patch_decomposition_figure(r));
  const std::string preview_svg = svg_document(patch_preview_figure(r));
  content["decomposition.svg"] = decomposition_svg;
  content["preview.svg"] = preview_svg;
  std::vector<std::string> files;
  for (const auto& [file, text] : content) files.push_back(file);
  files.insert(files.end(), {"deviation.ply", "report.html", "report.json"});
  if (p.thinning) files.push_back("thinned.ply");
  if (r.interrogation)
    for (const std::string& f : interrogation_file_names()) files.push_back(f);
  std::sort(files.begin(), files.end());
  content["report.html"] = html_report(r, decomposition_svg, preview_svg, files);
  content["report.json"] = report_json_text(patch_report_json(r, files));
  OutputTransaction outputs(dir);  // all or nothing
  for (const auto& [name, text] : content) outputs.add(name, text);
  add_deviation_ply(outputs, dir, r.points, p.distances, p.error.p99);
  if (p.thinning)
    outputs.add("thinned.ply",
                ply_writer(dir / "thinned.ply", select_columns(r.points, p.thinning->kept)));
  if (r.interrogation) add_interrogation_files(outputs, dir, *r.interrogation, title);
  outputs.commit();
  return files;
}

}  // namespace polarform
