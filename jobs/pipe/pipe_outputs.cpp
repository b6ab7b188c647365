#include "jobs/pipe/pipe_outputs.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "export/atomic_file.h"
#include "export/html_report.h"
#include "export/iges_writer.h"
#include "export/step_writer.h"
#include "export/svg_plot.h"
#include "export/x3d_writer.h"
#include "jobs/report/exchange_headers.h"
#include "jobs/report/output_files.h"
#include "polarform_version.h"
#include "src/number_text.h"
#include "src/nurbs/tessellation.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

double curvature_at(const NurbsCurve3d& c, double t) {
  const NurbsCurve3d::Points d = c.derivatives(t, 2);
  const double speed = d[1].norm();
  return speed > 0 ? d[1].cross(d[2]).norm() / (speed * speed * speed) : 0.0;
}

// A bound as JSON: null where it is infinite (no such mode).
json bound(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

std::string frame_name(FrameRule f) {
  return f == FrameRule::rmf ? "rmf" : f == FrameRule::frenet ? "frenet" : "fixed";
}

}  // namespace

Figure pipe_curvature_figure(const PipeJobResult& r) {
  Figure f(900, 450);
  f.title = "curvature of the spine: κ_max = " + format_trimmed(r.curvature.kappa_max, 5) +
            " 1/mm (1/κ_max = " + format_trimmed(1 / r.curvature.kappa_max, 5) + " mm)";
  Plot& p = f.add_panel();
  p.x_label = r.chord_length_parameter ? "length along the spine (chord-length parameter) [mm]"
                                       : "spine parameter t";
  p.y_label = "curvature κ [1/mm]";
  Series k{"κ", {}, {}, Series::Style::line, "#14c"};
  const std::vector<double> ts =
      tessellation_parameters(r.spine.knots(), r.spine.front(), r.spine.back(), 2000);
  const double limit = 1 / r.radius;
  double band_start = std::numeric_limits<double>::quiet_NaN();
  bool labelled = false;
  for (const double t : ts) {
    const double kappa = curvature_at(r.spine, t);
    k.x.push_back(t);
    k.y.push_back(kappa);
    const bool over = kappa >= limit;
    if (over && std::isnan(band_start)) band_start = t;
    if (!over && !std::isnan(band_start)) {
      p.add_band(band_start, t, labelled ? "" : "κ·r ≥ 1: the pipe folds", "#e44");
      labelled = true;
      band_start = std::numeric_limits<double>::quiet_NaN();
    }
  }
  if (!std::isnan(band_start))
    p.add_band(band_start, ts.back(), labelled ? "" : "κ·r ≥ 1: the pipe folds", "#e44");
  p.add(k);
  p.add_horizontal_line(limit, "1/r = " + format_trimmed(limit, 4) + " 1/mm");
  return f;
}

json pipe_report_json(const PipeJobResult& r, const std::vector<std::string>& files) {
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "pipe";
  j["input"] = {{"file", r.input.string()}, {"points", r.points.cols()}};
  j["radius_mm"] = r.radius;
  j["frame"] = frame_name(r.frame);
  j["spine"] = {{"closed", r.closed},
                {"degree", r.spine.degree()},
                {"control_points", r.spine.size()},
                {"length_mm", r.length},
                {"kappa_max_per_mm", r.curvature.kappa_max},
                {"at_t", r.curvature.t_at},
                {"parameter", r.chord_length_parameter ? "chord length of the spine points [mm]"
                                                       : "the NURBS spine's own"}};
  const PipeBounds& b = r.bounds;
  j["bounds_mm"] = {{"local", bound(b.local)},
                    {"end_end", bound(b.end_end)},
                    {"body_body", bound(b.body_body)},
                    {"end_body", bound(b.end_body)},
                    {"delta", bound(b.delta)}};
  j["limiting_mode"] = b.limiting_mode;
  j["limiting_at_t"] = json::array({b.t1, b.t2});
  j["nonsingular"] = r.nonsingular;
  j["surface"] = {{"exact", r.pipe.exact},
                  {"degrees", json::array({r.pipe.surface.degree_u(), r.pipe.surface.degree_v()})},
                  {"control_net", json::array({r.pipe.surface.size_u(), r.pipe.surface.size_v()})},
                  {"sections", r.pipe.sections},
                  {"tolerance_mm", r.tolerance},
                  {"max_error_mm", r.pipe.max_error}};
  j["warnings"] = r.warnings;
  j["timings_s"] = {{"total", r.seconds}};
  j["files"] = files;
  return j;
}

std::vector<std::string> write_pipe_outputs(const PipeJobResult& r,
                                            const std::filesystem::path& dir) {
  std::map<std::string, std::string> content;
  const std::string title = "polarform pipe around " + r.input.filename().string();
  auto [iges, step] = exchange_headers(title);
  IgesWriter pipe_igs, spine_igs;
  pipe_igs.add(r.pipe.surface, "PIPE");
  spine_igs.add(r.spine, "SPINE");
  iges.file_name = "pipe.igs";
  content["pipe.igs"] = pipe_igs.str(iges);
  iges.file_name = "spine.igs";
  content["spine.igs"] = spine_igs.str(iges);
  StepWriter stp(r.input.stem().string());
  stp.add(r.pipe.surface, "pipe");
  step.file_name = "pipe.stp";
  content["pipe.stp"] = stp.str(step);
  X3dWriter x3d;
  x3d.add(r.pipe.surface, "pipe");
  x3d.add(r.spine, "spine");
  content["pipe.x3d"] = x3d.str(title);
  const std::string curvature = svg_document(pipe_curvature_figure(r));
  content["curvature.svg"] = curvature;
  std::vector<std::string> files;
  for (const auto& [file, text] : content) files.push_back(file);
  files.insert(files.end(), {"report.html", "report.json"});
  std::sort(files.begin(), files.end());
  const PipeBounds& b = r.bounds;
  HtmlReport html("polarform pipe report: " + r.input.filename().string());
  const auto mm = [](double x) {
    return std::isfinite(x) ? format_trimmed(x, 6) : std::string("none");
  };
  html.add_key_figures(
      {{"radius [mm]", format_trimmed(r.radius, 6)},
       {"δ = bound on the radius [mm]", mm(b.delta) + " (" + b.limiting_mode + ")"},
       {"nonsingular", r.nonsingular ? "yes" : "NO"},
       {"surface", std::string(r.pipe.exact ? "exact" : "approximate") + ", max error " +
                       format_trimmed(r.pipe.max_error, 4) + " mm"}});
  html.add_table({"mode", "bound [mm]"},
                 {{"local: 1/κ_max", mm(b.local)},
                  {"end circle to end circle", mm(b.end_end)},
                  {"body to body: half the shortest double normal", mm(b.body_body)},
                  {"end circle to body", mm(b.end_body)}});
  for (const std::string& w : r.warnings) html.add_paragraph("Warning: " + w);
  html.add_svg(curvature,
               "The spine's curvature against its length; a pipe of radius r folds "
               "where κ·r ≥ 1 (shaded).");
  html.add_file_list(files);
  content["report.html"] = html.html();
  content["report.json"] = report_json_text(pipe_report_json(r, files));
  write_files_atomically(dir, content);
  return files;
}

}  // namespace polarform
