#include "jobs/study/study_job.h"

#include <chrono>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "export/atomic_file.h"
#include "export/csv_writer.h"
#include "export/svg_plot.h"
#include "jobs/cam/cam_job.h"
#include "jobs/report/output_files.h"
#include "jobs/study/study_plots.h"
#include "polarform_version.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

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
  content["study.svg"] = svg_document(study_figure(r, design_name));
  content["deviation.svg"] = svg_document(deviation_figure(r));
  std::vector<std::string> files;
  for (const auto& [name, text] : content) files.push_back(name);
  files.push_back("report.json");
  const nlohmann::ordered_json report = {{"polarform_version", POLARFORM_VERSION},
                                         {"command", "study"},
                                         {"design", design_name},
                                         {"rows", rows},
                                         {"files", files},
                                         {"seconds", r.seconds}};
  content["report.json"] = report_json_text(report);
  write_files_atomically(dir, content);
  return files;
}

}  // namespace polarform
