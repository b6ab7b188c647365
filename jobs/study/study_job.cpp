#include "jobs/study/study_job.h"

#include <chrono>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "export/atomic_file.h"
#include "export/csv_writer.h"
#include "export/svg_plot.h"
#include "jobs/cam/cam_job.h"
#include "polarform_version.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

Series line(std::string label, std::vector<double> x, std::vector<double> y, std::string color) {
  Series s;
  s.label = std::move(label);
  s.x = std::move(x);
  s.y = std::move(y);
  s.style = Series::Style::line_markers;
  s.color = std::move(color);
  return s;
}

Figure study_figure(const StudyJobResult& r, const std::string& name) {
  Figure f(900, 760);
  f.title = "Tolerance study: " + name;
  f.shared_x = true;
  std::vector<double> tol, q, rqb, cubic, qa, ra;
  for (const StudyRow& row : r.rows) {
    tol.push_back(row.tolerance);
    q.push_back(row.quartic.control_points);
    rqb.push_back(row.rqb.control_points);
    cubic.push_back(row.cubic.control_points);
    qa.push_back(row.quartic.arcs);
    ra.push_back(row.rqb.arcs);
  }
  Plot& points = f.add_panel();
  points.log_x = points.log_y = true;
  points.x_label = "tolerance ε [mm]";
  points.y_label = "control points";
  points.add(line("quasi-uniform quartic base (exact degree)", tol, q, "#0072b2"));
  points.add(line("RQB base", tol, rqb, "#e69f00"));
  points.add(line("cubic through sampled points", tol, cubic, "#999999"));
  Plot& arcs = f.add_panel();
  arcs.log_y = true;
  arcs.y_label = "base-circle arcs";
  arcs.add(line("quasi-uniform quartic", tol, qa, "#0072b2"));
  arcs.add(line("RQB", tol, ra, "#e69f00"));
  return f;
}

Figure deviation_figure(const StudyJobResult& r) {
  Figure f(900, 560);
  f.title = "Max angle deviation of a base arc (Bae 2002, Fig. 5.4)";
  Plot& plot = f.add_panel();
  plot.log_x = plot.log_y = true;
  plot.x_label = "arc angle 2φ [deg]";
  plot.y_label = "max |ξ(η) − 2φη| [rad]";
  std::vector<double> x, rqb, minimax, printed;
  for (const DeviationRow& d : r.deviation) {
    x.push_back(d.arc_angle * kDegreesPerRadian);
    rqb.push_back(d.rqb);
    minimax.push_back(d.quartic_minimax);
    printed.push_back(d.quartic_printed);
  }
  auto series = [](std::string label, std::vector<double> x, std::vector<double> y, Series::Style s,
                   std::string color) {
    Series out;
    out.label = std::move(label), out.x = std::move(x), out.y = std::move(y), out.style = s;
    out.color = std::move(color);
    return out;
  };
  plot.add(series("RQB arc", x, rqb, Series::Style::line, "#e69f00"));
  plot.add(series("quartic, minimax α", x, minimax, Series::Style::line, "#0072b2"));
  plot.add(series("quartic, printed α", x, printed, Series::Style::dashed, "#56b4e9"));
  return f;
}

}  // namespace

StudyJobResult run_study_job(const CamProject& project, const std::vector<double>& tolerances,
                             const std::function<void(double)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  for (double tol : tolerances)
    if (!(tol >= kMinTolerance))
      throw InputError("study tolerance " + format_round_trip(tol) + " mm: expected >= " +
                       format_round_trip(kMinTolerance) + " mm");
  StudyJobResult r;
  r.rows = tolerance_study(cam_profile_function(project.cam), tolerances, progress);
  r.deviation = angle_deviation_study(40);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::vector<std::string> write_study_outputs(const StudyJobResult& r, const std::string& design_name,
                                             const std::filesystem::path& dir) {
  std::map<std::string, std::string> content;
  CsvWriter study({"tolerance [mm]", "quartic arcs", "quartic control points", "quartic degree",
                   "quartic max radial error [mm]", "rqb arcs", "rqb control points", "rqb degree",
                   "rqb max radial error [mm]", "cubic points", "cubic control points",
                   "cubic max radial error [mm]"});
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const StudyRow& row : r.rows) {
    study.row({row.tolerance, double(row.quartic.arcs), double(row.quartic.control_points),
               double(row.quartic.degree), row.quartic.max_radial_error, double(row.rqb.arcs),
               double(row.rqb.control_points), double(row.rqb.degree), row.rqb.max_radial_error,
               double(row.cubic.points), double(row.cubic.control_points),
               row.cubic.max_radial_error});
    auto method = [](const StudyMethodResult& m) {
      return nlohmann::ordered_json{{"arcs", m.arcs},
                                    {"points", m.points},
                                    {"degree", m.degree},
                                    {"control_points", m.control_points},
                                    {"max_radial_error_mm", m.max_radial_error}};
    };
    rows.push_back({{"tolerance_mm", row.tolerance},
                    {"quasi_uniform", method(row.quartic)},
                    {"rqb", method(row.rqb)},
                    {"cubic_through_points", method(row.cubic)}});
  }
  CsvWriter deviation({"arc angle [deg]", "rqb max angle deviation [rad]",
                       "quartic minimax max angle deviation [rad]",
                       "quartic printed max angle deviation [rad]"});
  for (const DeviationRow& d : r.deviation)
    deviation.row({d.arc_angle * kDegreesPerRadian, d.rqb, d.quartic_minimax, d.quartic_printed});
  content["study.csv"] = study.str();
  content["deviation.csv"] = deviation.str();
  content["study.svg"] = study_figure(r, design_name).svg();
  content["deviation.svg"] = deviation_figure(r).svg();
  std::vector<std::string> files;
  for (const auto& [name, text] : content) files.push_back(name);
  files.push_back("report.json");
  const nlohmann::ordered_json report = {{"polarform_version", POLARFORM_VERSION},
                                         {"command", "study"},
                                         {"design", design_name},
                                         {"rows", rows},
                                         {"files", files},
                                         {"seconds", r.seconds}};
  content["report.json"] = report.dump(2) + "\n";
  write_files_atomically(dir, content);
  return files;
}

}  // namespace polarform
