#include "jobs/study/study_job.h"

#include <chrono>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "designers/convert/occt_peer.h"
#include "designers/convert/sisl_peer.h"
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

namespace {

// study.csv's header: the methods' columns, then (with peers) the peers' and the ratios.
std::vector<std::string> study_columns(bool peers) {
  std::vector<std::string> out = {"tolerance [mm]",
                                  "quartic arcs",
                                  "quartic control points",
                                  "quartic degree",
                                  "quartic max radial error [mm]",
                                  "rqb arcs",
                                  "rqb control points",
                                  "rqb degree",
                                  "rqb max radial error [mm]",
                                  "cubic points",
                                  "cubic control points",
                                  "cubic max radial error [mm]",
                                  "exact arcs",
                                  "exact control points",
                                  "exact degree",
                                  "exact max radial error [mm]",
                                  "degree 3 control points",
                                  "degree 3 max radial error [mm]"};
  if (!peers) return out;
  for (const char* peer : {"occt degree 3", "occt degree 3..8"})
    for (const char* column :
         {" control points", " degree", " max radial error [mm]", " tol3d [mm]"})
      out.push_back(std::string(peer) + column);
  for (const char* peer : {"sisl degree 3", "sisl degree 3..8"})
    for (const char* column :
         {" control points", " degree", " max radial error [mm]", " eeps [mm]"})
      out.push_back(std::string(peer) + column);
  for (const char* ratio :
       {"exact / best peer control points", "degree 3 / best peer control points",
        "degree 3 / occt degree 3 control points", "degree 3 / sisl degree 3 control points"})
    out.push_back(ratio);
  return out;
}

// One study.csv row; a peer that found no curve leaves nan.
std::vector<double> study_values(const StudyRow& row, bool peers) {
  std::vector<double> out = {row.tolerance,
                             double(row.quartic.arcs),
                             double(row.quartic.control_points),
                             double(row.quartic.degree),
                             row.quartic.max_radial_error,
                             double(row.rqb.arcs),
                             double(row.rqb.control_points),
                             double(row.rqb.degree),
                             row.rqb.max_radial_error,
                             double(row.cubic.points),
                             double(row.cubic.control_points),
                             row.cubic.max_radial_error,
                             double(row.exact.arcs),
                             double(row.exact.control_points),
                             double(row.exact.degree),
                             row.exact.max_radial_error,
                             double(row.degree3.control_points),
                             row.degree3.max_radial_error};
  if (!peers) return out;
  constexpr double kNone = StudyPeerRatios::kNone;
  for (const StudyPeerResult* p :
       {&row.occt_degree3, &row.occt_best, &row.sisl_degree3, &row.sisl_best})
    for (double v :
         {double(p->control_points), double(p->degree), p->max_radial_error, p->peer_tolerance})
      out.push_back(p->found ? v : kNone);
  for (double v : {row.ratios.exact_to_best, row.ratios.degree3_to_best,
                   row.ratios.degree3_to_occt_degree3, row.ratios.degree3_to_sisl_degree3})
    out.push_back(v);
  return out;
}

// One row of report.json; NaN ratios are written as null.
nlohmann::ordered_json report_row(const StudyRow& row, bool peers) {
  const auto method = [](const StudyMethodResult& m) {
    return nlohmann::ordered_json{{"arcs", m.arcs},
                                  {"points", m.points},
                                  {"degree", m.degree},
                                  {"control_points", m.control_points},
                                  {"max_radial_error_mm", m.max_radial_error}};
  };
  nlohmann::ordered_json out = {
      {"tolerance_mm", row.tolerance},   {"quasi_uniform", method(row.quartic)},
      {"rqb", method(row.rqb)},          {"cubic_through_points", method(row.cubic)},
      {"exact_form", method(row.exact)}, {"degree_3", method(row.degree3)}};
  if (!peers) return out;
  // tolerance_key: the name of the tolerance the peer was handed (OCCT's Tol3D, SISL's eeps).
  const auto peer = [](const StudyPeerResult& p, const char* tolerance_key) {
    if (!p.found) return nlohmann::ordered_json{{"found", false}};
    return nlohmann::ordered_json{{"found", true},
                                  {"degree", p.degree},
                                  {"control_points", p.control_points},
                                  {"max_radial_error_mm", p.max_radial_error},
                                  {tolerance_key, p.peer_tolerance}};
  };
  out["occt_degree_3"] = peer(row.occt_degree3, "tol3d_mm");
  out["occt_degree_3_to_8"] = peer(row.occt_best, "tol3d_mm");
  out["sisl_degree_3"] = peer(row.sisl_degree3, "eeps_mm");
  out["sisl_degree_3_to_8"] = peer(row.sisl_best, "eeps_mm");
  out["control_point_ratios"] = {{"exact_to_best_peer", row.ratios.exact_to_best},
                                 {"degree_3_to_best_peer", row.ratios.degree3_to_best},
                                 {"degree_3_to_occt_degree_3", row.ratios.degree3_to_occt_degree3},
                                 {"degree_3_to_sisl_degree_3", row.ratios.degree3_to_sisl_degree3}};
  return out;
}

}  // namespace

std::string missing_peers_note(const StudyOptions& options) {
  return options.peers ? "peers: neither Open CASCADE nor SISL is available in this build, no peer "
                         "columns"
                       : "peers: not asked for (--no-peers), no peer columns";
}

StudyJobResult run_study_job(const CamProject& project, const std::vector<double>& tolerances,
                             const std::function<void(double)>& progress,
                             const StudyOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  for (double tol : tolerances)
    if (!(tol >= kMinTolerance))
      throw InputError("study tolerance " + format_round_trip(tol) + " mm: expected >= " +
                       format_round_trip(kMinTolerance) + " mm");
  StudyJobResult r;
  r.rows = tolerance_study(cam_profile_function(project.cam), tolerances, progress, options);
  r.peers = options.peers && (kOcctPeersAvailable || kSislPeersAvailable);
  r.deviation = angle_deviation_study(40);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::vector<std::string> write_study_outputs(const StudyJobResult& r, const std::string& design_name,
                                             const std::filesystem::path& dir) {
  std::map<std::string, std::string> content;
  CsvWriter study(study_columns(r.peers));
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const StudyRow& row : r.rows) {
    study.row(study_values(row, r.peers));
    rows.push_back(report_row(row, r.peers));
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
                                         {"peers", r.peers},
                                         {"rows", rows},
                                         {"files", files},
                                         {"seconds", r.seconds}};
  content["report.json"] = report_json_text(report);
  write_files_atomically(dir, content);
  return files;
}

}  // namespace polarform
