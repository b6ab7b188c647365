#include "jobs/scan_cam/scan_cam_outputs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "export/atomic_file.h"
#include "export/csv_writer.h"
#include "export/dxf_writer.h"
#include "export/html_report.h"
#include "export/iges_writer.h"
#include "export/step_writer.h"
#include "export/svg_plot.h"
#include "export/x3d_writer.h"
#include "jobs/fit/profile_curvature_figure.h"
#include "jobs/fit/profile_interrogation.h"
#include "jobs/report/exchange_headers.h"
#include "jobs/report/output_files.h"
#include "jobs/scan_cam/scan_cam_design_report.h"
#include "jobs/scan_cam/scan_cam_plots.h"
#include "jobs/scan_cam/scan_cam_project.h"
#include "polarform_version.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

constexpr int kGrid = 720;  // cam angles of svaj.csv (0.5° apart)
using json = nlohmann::ordered_json;

// --write-project's target must be a file in an existing folder.
void check_project_target(const std::filesystem::path& project) {
  const std::filesystem::path folder =
      project.has_parent_path() ? project.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(folder))
    throw InputError("--write-project " + project.string() + ": the folder " + folder.string() +
                     " does not exist");
  if (std::filesystem::is_directory(project))
    throw InputError("--write-project " + project.string() + ": is a folder; expected a file name");
}

double wrapped_degrees(double theta) {
  const double t = std::fmod(theta, 2 * std::numbers::pi);
  return (t < 0 ? t + 2 * std::numbers::pi : t) * kDegreesPerRadian;
}

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json stats(const ErrorStats& e) {
  return json{{"rms", e.rms}, {"max", e.max}, {"p95", e.p95}, {"p99", e.p99}, {"count", e.count}};
}

std::vector<double> cam_angles() {
  std::vector<double> t;
  for (int i = 0; i < kGrid; ++i) t.push_back(2 * std::numbers::pi * i / kGrid);
  return t;
}

std::string svaj_csv(const ScanCamJobResult& r) {
  std::vector<std::string> headers = {"cam angle theta [deg]", "s [mm]", "v [mm/rad]",
                                      "a [mm/rad^2]", "j [mm/rad^3]"};
  if (r.nominal)
    for (const char* h :
         {"nominal s [mm]", "nominal v [mm/rad]", "nominal a [mm/rad^2]", "nominal j [mm/rad^3]"})
      headers.push_back(h);
  CsvWriter csv(headers);
  for (double theta : cam_angles()) {
    double d[4];
    r.scan.displacement_derivatives(theta, 3, d);
    std::vector<double> row = {theta * kDegreesPerRadian, d[0], d[1], d[2], d[3]};
    if (r.nominal) {
      double n[4];
      r.nominal->program().derivatives(theta, 3, n);
      row.insert(row.end(), n, n + 4);
    }
    csv.row(row);
  }
  return csv.str();
}

std::string deviation_csv(const NominalComparison& c) {
  CsvWriter csv({"cam angle theta [deg]", "radial deviation [mm]", "normal deviation [mm]"});
  for (std::size_t i = 0; i < c.theta.size(); ++i)
    csv.row({c.theta[i] * kDegreesPerRadian, c.radial[i], c.normal[i]});
  return csv.str();
}

// Largest |x| over a revolution of the recovered s^(k), and the lift max s − min s.
// Farin's refit of s along the recovered design (segmented_displacement.h), or why there is none.
json refit_json(const DisplacementFairing& f) {
  if (!f.refit) return {{"applied", false}, {"skipped", f.refit_skipped}};
  const SegmentedDisplacement& r = *f.refit;
  return {{"applied", true},
          {"smoothing", "discrepancy principle: RSS = n·σ̂², σ̂ from GCV on the same pieces"},
          {"noise_mm", r.noise},
          {"gcv_dof", r.gcv_dof},
          {"lambda", r.lambda},
          {"dof", r.dof},
          {"rss_mm2", r.rss},
          {"target_rss_mm2", r.target_rss},
          {"discrepancy_met", r.discrepancy_met},
          {"boundaries", r.breaks},
          {"dwells", r.dwells},
          {"deviation_mm", f.refit_deviation}};
}

json motion_json(const ScannedCam& s) {
  double lo = INFINITY, hi = -INFINITY, peak[4] = {0, 0, 0, 0};
  for (double theta : cam_angles()) {
    double d[4];
    s.displacement_derivatives(theta, 3, d);
    lo = std::min(lo, d[0]);
    hi = std::max(hi, d[0]);
    for (int k = 1; k < 4; ++k) peak[k] = std::max(peak[k], std::abs(d[k]));
  }
  return json{{"lift_mm", hi - lo},
              {"min_s_mm", lo},
              {"max_abs_velocity_mm_per_rad", peak[1]},
              {"max_abs_acceleration_mm_per_rad2", peak[2]},
              {"max_abs_jerk_mm_per_rad3", peak[3]}};
}

// The recovered design: the segments with their laws and uncertainties, and the re-designed
// cam's deviation from the scan.
void add_design_section(HtmlReport& html, const ScanCamJobResult& r) {
  const RecoveredDesign& d = *r.design;
  html.add_heading("Recovered design");
  std::vector<std::vector<std::string>> rows;
  for (const IdentifiedMotion& m : d.motions) {
    const LawFit& f = m.law();
    std::string others;
    for (std::size_t i : m.indistinguishable)
      others += (others.empty() ? "" : ", ") + law_label(m.candidates[i].shape);
    rows.push_back({std::string(segment_kind_name(m.kind)), law_label(f.shape),
                    format_trimmed(wrapped_degrees(f.start - d.phase), 3) + "° ± " +
                        format_trimmed(f.sd[0] * kDegreesPerRadian, 3) + "°",
                    format_trimmed(wrapped_degrees(f.end - d.phase), 3) + "° ± " +
                        format_trimmed(f.sd[1] * kDegreesPerRadian, 3) + "°",
                    format_trimmed(std::abs(f.lift), 4) + " ± " + number_text(f.sd[3]) + " mm",
                    number_text(f.rms() * 1e3) + " µm", others.empty() ? "—" : others});
  }
  html.add_table({"motion", "law", "from", "to", "lift", "rms residual", "not told apart from"},
                 rows);
  const NominalComparison& c = d.deviation;
  html.add_paragraph(
      "Angles are in the recovered design's frame: design cam angle = scan cam angle − " +
      format_trimmed(d.phase * kDegreesPerRadian, 4) + "°. Base radius " +
      format_trimmed(d.design.base_radius, 4) +
      " mm. Laws were chosen by least BIC with the "
      "displacement noise σ̂; the re-designed profile deviates from the scan's fitted profile by " +
      number_text(c.normal_stats.rms * 1e3) + " µm rms, " + number_text(c.normal_stats.max * 1e3) +
      " µm max (normal), against a profile noise of " + number_text(r.scan.contour_noise * 1e3) +
      " µm.");
}

std::string html_report(const ScanCamJobResult& r, const json& report,
                        const std::map<std::string, std::string>& svgs) {
  const ScannedCam& s = r.scan;
  HtmlReport html("polarform scan-cam report: " + r.input.filename().string());
  std::vector<std::pair<std::string, std::string>> key = {
      {"scan", std::string(s.profile.three_d ? "3D" : "2D") + ", " + std::to_string(r.points) +
                   " points, " + std::to_string(s.contour.cols()) + " on the contour"},
      {"profile noise σ̂", number_text(s.contour_noise * 1e3) + " µm"},
      {"displacement noise σ̂", number_text(s.displacement.noise * 1e3) + " µm"},
      {"recovered s standard error",
       format_trimmed(s.displacement.standard_error * 1e3, 3) + " µm"},
      {"base radius", format_trimmed(s.base_radius, 4) + " mm"},
      {"lift", format_trimmed(report["motion"]["lift_mm"].get<double>(), 4) + " mm"}};
  if (s.alignment)
    key.emplace_back("phase to nominal", format_trimmed(s.alignment->phase * kDegreesPerRadian, 4) +
                                             "°" + (s.mirrored ? " (mirrored)" : ""));
  if (r.comparison) {
    key.emplace_back("max |normal deviation|",
                     format_trimmed(r.comparison->normal_stats.max * 1e3, 3) + " µm");
    key.emplace_back("rms normal deviation",
                     number_text(r.comparison->normal_stats.rms * 1e3) + " µm");
  }
  if (r.tolerance)
    key.emplace_back("tolerance ±" + format_trimmed(*r.tolerance * 1e3, 3) + " µm",
                     r.within_tolerance ? "met" : "NOT MET");
  html.add_key_figures(key);
  html.add_heading("How the scan was read");
  html.add_paragraph("Axis: " + s.profile.axis_reason + ".");
  html.add_paragraph("Centre of rotation: " + s.profile.centre_reason + ".");
  html.add_paragraph("Follower (" + r.follower_source +
                     "): " + std::string(follower_kind_name(s.follower.kind)) + ", offset " +
                     format_trimmed(s.follower.offset, 4) + " mm" +
                     (s.follower.kind == FollowerKind::Roller
                          ? ", roller radius " + format_trimmed(s.follower.roller_radius, 4) + " mm"
                          : std::string()) +
                     "; rotation " + std::string(rotation_name(s.rotation)) + ".");
  html.add_paragraph("Smoothing: the displacement is a periodic degree-" +
                     std::to_string(s.displacement.height.degree()) +
                     " B-spline whose fairness weight λ = " + number_text(s.displacement.lambda) +
                     " was chosen by generalized cross-validation (" +
                     format_trimmed(s.displacement.dof, 1) +
                     " effective parameters). The noise floor of the " +
                     "samples is σ̂ = " + number_text(s.displacement.noise * 1e3) +
                     " µm; differences below it are not resolved.");
  html.add_heading("Profile");
  html.add_svg(svgs.at("profile.svg"),
               "The scanned points and the fitted NURBS profile in the cam frame.");
  html.add_svg(svgs.at("deviation.svg"),
               r.comparison ? "Deviation from the nominal profile against cam angle."
                            : "Scanned points about the fitted profile.");
  html.add_heading("Recovered motion");
  html.add_svg(svgs.at("svaj.svg"),
               "Recovered s, v, a, j against cam angle (per radian of cam angle).");
  if (r.fairing)
    html.add_svg(svgs.at("fairing.svg"),
                 "The recovered acceleration before and after fairing s(θ) (Farin: refitted "
                 "along the recovered design, then its knots faired), and the jumps of its p-th "
                 "derivative at the knots faired.");
  if (r.comparison) {
    html.add_svg(svgs.at("svaj_difference.svg"), "Recovered minus nominal s, v, a, j.");
    std::vector<std::vector<std::string>> rows;
    const char* names[4] = {"s [mm]", "v [mm/rad]", "a [mm/rad²]", "j [mm/rad³]"};
    for (std::size_t k = 0; k < 4; ++k)
      rows.push_back({names[k], format_trimmed(r.comparison->svaj_stats[k].rms, 6),
                      format_trimmed(r.comparison->svaj_stats[k].max, 6)});
    html.add_table({"quantity", "rms difference", "max |difference|"}, rows);
  }
  if (r.design) add_design_section(html, r);
  html.add_file_list(report["files"].get<std::vector<std::string>>());
  return html.html();
}

}  // namespace

json scan_cam_report_json(const ScanCamJobResult& r, const std::vector<std::string>& files,
                          const std::filesystem::path& project) {
  const ScannedCam& s = r.scan;
  const CamProfile& p = s.profile;
  const FitReport& fit = s.fit.report;
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "scan-cam";
  j["input"] = {{"file", r.input.string()}, {"points", r.points}, {"dropped", r.dropped}};
  j["scan"] = {{"kind", p.three_d ? "3d" : "2d"},
               {"contour_points", s.contour.cols()},
               {"bore_points", p.bore.cols()},
               {"axis_reason", p.axis_reason},
               {"centre_reason", p.centre_reason}};
  if (p.three_d) {
    j["scan"]["thickness_mm"] = std::abs(p.thickness);
    j["scan"]["face_flatness_mm"] = p.face_flatness;
    j["scan"]["face_points"] = p.face_points;
  }
  if (p.bore_circle)
    j["bore"] = {{"diameter_mm", 2 * p.bore_circle->radius}, {"rms_mm", p.bore_circle->rms}};
  j["cam_frame"] = {{"origin", vec(s.cam_frame.origin)},
                    {"i", vec(s.cam_frame.axes.col(0))},
                    {"j", vec(s.cam_frame.axes.col(1))},
                    {"k", vec(s.cam_frame.axes.col(2))},
                    {"meaning",
                     "scan coordinates of the cam frame: origin = centre of rotation, "
                     "k = axis, follower on +j at cam angle 0"}};
  j["follower"] = {{"kind", follower_kind_name(s.follower.kind)},
                   {"offset_mm", s.follower.offset},
                   {"roller_radius_mm", s.follower.roller_radius},
                   {"rotation", rotation_name(s.rotation)},
                   {"source", r.follower_source}};
  j["profile"] = {{"degree", s.fit.curve.degree()}, {"control_points", s.fit.curve.size()},
                  {"F_degree", fit.degree_v},       {"F_control_values", fit.size_v},
                  {"closed", s.fit.closed},         {"fairness_lambda", fit.lambda},
                  {"error_mm", stats(fit.error)},   {"noise_mm", s.contour_noise}};
  j["displacement"] = {{"degree", s.displacement.height.degree()},
                       {"fairness_lambda", s.displacement.lambda},
                       {"effective_parameters", s.displacement.dof},
                       {"noise_mm", s.displacement.noise},
                       {"standard_error_mm", s.displacement.standard_error},
                       {"residual_mm", stats(s.displacement.residual)},
                       {"rest_height_mm", s.rest_height},
                       {"measured_rest_height_mm", s.measured_rest_height},
                       {"base_radius_mm", s.base_radius}};
  j["motion"] = motion_json(s);
  if (s.alignment)
    j["alignment"] = {{"phase_deg", s.alignment->phase * kDegreesPerRadian},
                      {"mirrored", s.mirrored},
                      {"rms_radial_difference_mm", s.alignment->rms}};
  if (r.comparison) {
    const NominalComparison& c = *r.comparison;
    j["nominal"] = {{"file", r.nominal_file.string()},
                    {"base_radius_mm", r.nominal->base_radius()},
                    {"profile_radial_deviation_mm", stats(c.radial_stats)},
                    {"profile_normal_deviation_mm", stats(c.normal_stats)},
                    {"point_radial_deviation_mm", stats(c.point_stats)}};
    const char* names[4] = {"s_mm", "v_mm_per_rad", "a_mm_per_rad2", "j_mm_per_rad3"};
    for (std::size_t k = 0; k < 4; ++k)
      j["nominal"]["svaj_difference"][names[k]] = stats(c.svaj_stats[k]);
  }
  if (r.tolerance) j["tolerance"] = {{"band_mm", *r.tolerance}, {"within", r.within_tolerance}};
  j["resolution"] = resolution_json(r.resolution);
  j["design"] = design_json(r);
  if (!project.empty()) j["design"]["project_file"] = project.string();
  j["interrogation"] = interrogation_json(r.interrogation);
  if (const auto& f = r.fairing) {
    json knots = json::array();
    for (const FairingStep& k : f->fairing.steps)
      knots.push_back({{"u_deg", k.u * kDegreesPerRadian},
                       {"jump_before", k.jump_before},
                       {"jump_after", k.jump_after},
                       {"bound_mm", k.bound}});
    j["fairing"] = {{"method", fairing_method_name(f->fairing.method)},
                    {"tolerance_mm", f->fairing.tolerance},
                    {"passes", f->fairing.steps.size()},
                    {"knots_faired", knots},
                    {"max_jump_before", f->fairing.max_jump_before},
                    {"max_jump_after", f->fairing.max_jump_after},
                    {"measured_deviation_mm", f->fairing.measured_deviation},
                    {"refit", refit_json(f->fairing)},
                    {"acceleration_rms_error_before", nullptr},
                    {"acceleration_rms_error_after", nullptr}};
    if (f->acceleration_rms_before) {
      j["fairing"]["acceleration_rms_error_before"] = *f->acceleration_rms_before;
      j["fairing"]["acceleration_rms_error_after"] = *f->acceleration_rms_after;
    }
  }
  j["warnings"] = r.warnings;
  j["files"] = files;
  j["seconds"] = {{"read", r.read_seconds}, {"total", r.seconds}};
  return j;
}

std::vector<std::string> write_scan_cam_outputs(const ScanCamJobResult& r,
                                                const std::filesystem::path& dir,
                                                const std::filesystem::path& project) {
  // The project is rendered and its folder checked first, so a refusal writes nothing.
  const std::string project_xml =
      project.empty() ? std::string() : cam_project_xml(recovered_cam_project(r));
  if (!project.empty()) check_project_target(project);
  std::map<std::string, std::string> content;
  const NurbsCurve2d& curve = r.scan.fit.curve;
  const std::string title = "polarform scan-cam of " + r.input.filename().string();
  auto [iges, step] = exchange_headers(title);
  iges.file_name = "profile.igs";
  step.file_name = "profile.stp";
  IgesWriter igs;
  igs.add(curve, "SCANNED CAM PROFILE");
  StepWriter stp(r.input.stem().string());
  stp.add(curve, "scanned cam profile");
  X3dWriter x3d;
  x3d.add(curve, "profile");
  DxfWriter dxf(DxfOptions{std::max(10, curve.degree()), 1e-6});
  dxf.add(curve, "PROFILE");
  content["profile.igs"] = igs.str(iges);
  content["profile.stp"] = stp.str(step);
  content["profile.x3d"] = x3d.str(title);
  content["profile.dxf"] = dxf.str();
  content["svaj.csv"] = svaj_csv(r);
  content["curvature.csv"] = interrogation_csv(r.interrogation);
  std::map<std::string, std::string> svgs = {
      {"svaj.svg", svg_document(scan_svaj_figure(r))},
      {"deviation.svg", svg_document(scan_deviation_figure(r))},
      {"profile.svg", svg_document(scan_profile_figure(r))},
      {"curvature.svg", svg_document(profile_curvature_figure(
                            r.interrogation, "polar angle ψ of the contour, cam frame [deg]"))}};
  if (r.fairing) svgs["fairing.svg"] = svg_document(scan_fairing_figure(r));
  if (r.comparison) {
    svgs["svaj_difference.svg"] = svg_document(scan_svaj_difference_figure(r));
    content["deviation.csv"] = deviation_csv(*r.comparison);
  }
  content.insert(svgs.begin(), svgs.end());
  std::vector<std::string> files;
  for (const auto& [name, text] : content) files.push_back(name);
  files.push_back("report.html");
  files.push_back("report.json");
  std::sort(files.begin(), files.end());
  const json report = scan_cam_report_json(r, files, project);
  content["report.json"] = report_json_text(report);
  content["report.html"] = html_report(r, report, svgs);

  write_files_atomically(dir, content);
  if (!project.empty()) write_file_atomically(project, project_xml);
  return files;
}

}  // namespace polarform
