#include "jobs/viz/viz_outputs.h"

#include <algorithm>
#include <map>

#include "export/atomic_file.h"
#include "export/csv_writer.h"
#include "export/html_report.h"
#include "export/iges_writer.h"
#include "export/step_writer.h"
#include "export/svg_plot.h"
#include "export/x3d_field_scene.h"
#include "jobs/report/exchange_headers.h"
#include "jobs/report/output_files.h"
#include "jobs/viz/viz_plots.h"
#include "polarform_version.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

std::string control_values_csv(const ScalarFieldSurface& f) {
  CsvWriter csv({"i", "j", "x [mm]", "y [mm]", "z [mm]", "weight", "value"});
  const NurbsSurface& S = f.surface;
  for (int i = 0; i < S.size_u(); ++i)
    for (int j = 0; j < S.size_v(); ++j) {
      const Eigen::Vector3d p = S.control_point(i, j);
      csv.row({double(i), double(j), p.x(), p.y(), p.z(), S.weight(i, j),
               f.control_values[i * S.size_v() + j]});
    }
  return csv.str();
}

std::string html_report(const VizJobResult& r, const std::string& preview) {
  const ScalarFieldSurface& f = r.field;
  HtmlReport html("polarform viz report: " + r.input.filename().string());
  html.add_key_figures(
      {{"set-up", r.grid.setup == GridSetup::spherical ? "spherical" : "cylindrical"},
       {"values", std::to_string(r.grid.value.size()) + " of " + r.grid.value_name},
       {"surface",
        "S = (" + format_trimmed(r.scale, 6) + "·F + " + format_trimmed(r.offset, 6) + ")·B"},
       {"NURBS degree", "(" + std::to_string(f.surface.degree_u()) + ", " +
                            std::to_string(f.surface.degree_v()) + ")"},
       {"|F − p| rms / max",
        format_trimmed(f.fit_error.rms, 4) + " / " + format_trimmed(f.fit_error.max, 4)}});
  html.add_paragraph("Offset d: " + r.offset_reason +
                     ". The radius of the surface shows the value; "
                     "surface.x3d colours it by the value (viridis).");
  html.add_svg(preview, "The measured values and the fitted F along rows and columns of the grid.");
  return html.html();
}

}  // namespace

json viz_report_json(const VizJobResult& r, const std::vector<std::string>& files) {
  const ScalarFieldSurface& f = r.field;
  const ErrorStats& e = f.fit_error;
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "viz";
  j["input"] = {{"file", r.input.string()}, {"rows", r.grid.value.size()}};
  j["setup"] = r.grid.setup == GridSetup::spherical ? "spherical" : "cylindrical";
  j["value"] = r.grid.value_name;
  j["surface"] = "S = (s·F + d)·B, Bae 2002, eq. (5.6)";
  j["scale"] = r.scale;
  j["offset"] = r.offset;
  j["offset_reason"] = r.offset_reason;
  j["value_range"] = json::array({r.grid.value.minCoeff(), r.grid.value.maxCoeff()});
  j["control_value_range"] = json::array({f.min_value, f.max_value});
  j["degrees"] = {{"F", json::array({f.F.degree_u(), f.F.degree_v()})},
                  {"nurbs", json::array({f.surface.degree_u(), f.surface.degree_v()})}};
  j["control_net"] = {{"F", json::array({f.F.size_u(), f.F.size_v()})},
                      {"nurbs", json::array({f.surface.size_u(), f.surface.size_v()})}};
  j["fit_error"] = {{"rms", e.rms},
                    {"mean", e.mean},
                    {"max", e.max},
                    {"p95", e.p95},
                    {"p99", e.p99},
                    {"count", e.count},
                    {"kind", "|F(u_k, v_k) − p_k| in the value's units"}};
  j["colors"] = "viridis over control_value_range (surface.x3d: tessellation and control points)";
  j["files"] = files;
  j["seconds"] = r.seconds;
  return j;
}

std::vector<std::string> write_viz_outputs(const VizJobResult& r,
                                           const std::filesystem::path& dir) {
  std::map<std::string, std::string> content;
  const std::string title = "polarform viz of " + r.input.filename().string();
  auto [iges, step] = exchange_headers(title);
  iges.file_name = "surface.igs";
  step.file_name = "surface.stp";
  IgesWriter igs;
  igs.add(r.field.surface, "FIELD SURFACE");
  StepWriter stp(r.input.stem().string());
  stp.add(r.field.surface, "field surface");
  content["surface.igs"] = igs.str(iges);
  content["surface.stp"] = stp.str(step);
  content["surface.x3d"] = field_x3d(r.field, title);
  content["control_values.csv"] = control_values_csv(r.field);
  const std::string preview = svg_document(viz_preview_figure(r));
  content["preview.svg"] = preview;
  content["report.html"] = html_report(r, preview);
  std::vector<std::string> files;
  for (const auto& [file, text] : content) files.push_back(file);
  files.push_back("report.json");
  std::sort(files.begin(), files.end());
  content["report.json"] = report_json_text(viz_report_json(r, files));
  write_files_atomically(dir, content);
  return files;
}

}  // namespace polarform
