#include "jobs/fit/fit_outputs.h"

#include <algorithm>
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
#include "jobs/fit/fit_plots.h"
#include "jobs/fit/profile_curvature_figure.h"
#include "jobs/fit/profile_interrogation.h"
#include "jobs/fit/surface_fairing_stage.h"
#include "jobs/report/exchange_headers.h"
#include "jobs/report/output_files.h"
#include "polarform_version.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json stats(const ErrorStats& e) {
  return json{{"rms", e.rms}, {"mean", e.mean}, {"max", e.max},
              {"p95", e.p95}, {"p99", e.p99},   {"count", e.count}};
}

// How F's control net was chosen: GCV over net sizes (every candidate), or given / refined.
json net_json(const NetSelection& n) {
  json candidates = json::array();
  for (const NetCandidate& c : n.candidates)
    candidates.push_back({{"net", json::array({c.size_u, c.size_v})},
                          {"coefficients", c.coefficients},
                          {"rms_mm", c.rms},
                          {"gcv", c.gcv}});
  return json{{"chosen_by", n.automatic ? "gcv over net sizes" : "given net or tolerance"},
              {"noise_estimate_mm", n.noise},
              {"noise_reached", n.noise_reached},
              {"samples_used", n.samples},
              {"rule", "at most one coefficient per " + std::to_string(kSamplesPerCoefficient) +
                           " samples"},
              {"max_coefficients", n.max_coefficients},
              {"net", json::array({n.size_u, n.size_v})},
              {"stopped", n.stop},
              {"candidates", std::move(candidates)}};
}

// Whether F was made constant around the axis, and the F-test behind it.
json revolution_json(const RevolutionTest& t) {
  json j{{"mode", revolution_word(t.mode)}, {"rotational", t.rotational}, {"reason", t.reason}};
  if (t.tested)
    j["f_test"] = {{"samples", t.samples},
                   {"coefficients", json::array({t.params_rotational, t.params_full})},
                   {"rms_mm", json::array({t.rms_rotational, t.rms_full})},
                   {"gcv", json::array({t.gcv_rotational, t.gcv_full})},
                   {"f_statistic", t.f_statistic},
                   {"threshold", t.threshold},
                   {"p_value", t.p_value},
                   {"level", kRevolutionAlpha}};
  return j;
}

json frame_json(const LocalFrame& f, const std::string& reason) {
  return json{{"origin", vec(f.origin)},
              {"i", vec(f.axes.col(0))},
              {"j", vec(f.axes.col(1))},
              {"k", vec(f.axes.col(2))},
              {"reason", reason}};
}

json quadric_json(const QuadricFit& q) {
  static const char* names[10] = {"x2", "y2", "z2", "xy", "yz", "zx", "x", "y", "z", "1"};
  json c;
  for (int i = 0; i < 10; ++i) c[names[i]] = q.quadric.q[i];
  const QuadricClassification& k = q.classification;
  return json{{"type", to_string(k.type)},
              {"coefficients", c},
              {"equation",
               "x2·x² + y2·y² + z2·z² + xy·xy + yz·yz + zx·zx + x·x + y·y + z·z + 1·1 = 0 (Bae "
               "2002, eq. (4.1)), input coordinates, |q| = 1"},
              {"rank_Qu", k.rank_Qu},
              {"rank_Q", k.rank_Q},
              {"eigenvalues_Qu_normalised",
               json::array({k.eigenvalues[0], k.eigenvalues[1], k.eigenvalues[2]})},
              {"rms_sampson_distance_mm", q.rms_distance}};
}

json pole_json(PoleTreatment t, const PoleCheck& check, const std::optional<PoleReport>& p,
               const std::optional<PoleCap>& cap) {
  json j{{"treatment", pole_word(t)},
         {"nearest_data_deg", check.nearest_data * kDegreesPerRadian},
         {"extrapolated", check.extrapolated}};
  if (p)
    j["measured"] = {{"point", vec(p->point)},
                     {"gap_mm", p->gap},
                     {"normal_spread_deg", p->normal_spread * kDegreesPerRadian},
                     {"creased", check.creased}};
  if (cap)
    j["cap"] = {{"point", vec(cap->point)},
                {"normal", vec(cap->normal)},
                {"degree", json::array({cap->surface.degree_u(), cap->surface.degree_v()})},
                {"boundary_gap_mm", cap->boundary_gap},
                {"boundary_normal_angle_deg", cap->boundary_normal_angle * kDegreesPerRadian}};
  return j;
}

json times_json(const StageTimes& t) {
  return json{{"read", t.read},   {"frame", t.frame},     {"sync", t.sync},
              {"check", t.check}, {"knots", t.knots},     {"assembly", t.assembly},
              {"solve", t.solve}, {"product", t.product}, {"error", t.error},
              {"total", t.total}};
}

// The bundle's files as the report lists them: the rendered ones and deviation.ply (written
// apart, as binary), by name.
std::vector<std::string> fit_file_list(const std::map<std::string, std::string>& content,
                                       bool interrogated) {
  std::vector<std::string> files = {"deviation.ply", "report.html", "report.json"};
  if (interrogated) files.push_back("curvature.ply");
  for (const auto& [file, text] : content)
    if (file != "report.html" && file != "report.json") files.push_back(file);
  std::sort(files.begin(), files.end());
  return files;
}

std::string um(double mm) { return format_trimmed(mm * 1e3, 3) + " µm"; }

std::string html_report(const FitJobResult& r, const json& report, const std::string& preview) {
  const FitReport& rep = r.report();
  HtmlReport html("polarform fit report: " + r.input.filename().string());
  const ProfileFit* profile = std::get_if<ProfileFit>(&r.fit);
  const std::string degrees = profile ? std::to_string(profile->curve.degree())
                                      : "(" + std::to_string(rep.nurbs_degree_u) + ", " +
                                            std::to_string(rep.nurbs_degree_v) + ")";
  const std::string net =
      profile ? std::to_string(profile->curve.size())
              : std::to_string(rep.nurbs_size_u) + " × " + std::to_string(rep.nurbs_size_v);
  html.add_key_figures({{"method", r.method},
                        {"points", std::to_string(r.points.cols())},
                        {"NURBS degree", degrees},
                        {"control points", net},
                        {"rms distance", um(rep.error.rms)},
                        {"p95 / p99 distance", um(rep.error.p95) + " / " + um(rep.error.p99)},
                        {"max distance", um(rep.error.max)}});
  html.add_heading("Method");
  html.add_paragraph(r.reason);
  if (r.reject_outliers) html.add_paragraph(outlier_summary(r));
  for (const std::string& w : r.warnings) html.add_paragraph("Warning: " + w + ".");
  html.add_paragraph("Frame: " + report["frame"]["reason"].get<std::string>());
  if (report.contains("quadric") && !report["quadric"].is_null())
    html.add_paragraph("Best-fit quadric: " + report["quadric"]["type"].get<std::string>() +
                       " (rms Sampson distance " +
                       um(report["quadric"]["rms_sampson_distance_mm"].get<double>()) + ").");
  html.add_heading("Deviation");
  html.add_svg(preview,
               "Signed closest-point distances of the input points from the fitted geometry "
               "(+ away from the centre or axis).");
  const StageTimes& t = rep.times;
  html.add_table({"stage", "seconds"}, {{"read", format_trimmed(t.read, 4)},
                                        {"frame", format_trimmed(t.frame, 4)},
                                        {"sync", format_trimmed(t.sync, 4)},
                                        {"check", format_trimmed(t.check, 4)},
                                        {"knots", format_trimmed(t.knots, 4)},
                                        {"assembly", format_trimmed(t.assembly, 4)},
                                        {"solve", format_trimmed(t.solve, 4)},
                                        {"product", format_trimmed(t.product, 4)},
                                        {"error", format_trimmed(t.error, 4)},
                                        {"total", format_trimmed(t.total, 4)}});
  html.add_file_list(report["files"].get<std::vector<std::string>>());
  return html.html();
}

}  // namespace

double deviation_color_limit(const FitJobResult& r) { return std::max(r.report().error.p99, 1e-9); }

std::string outlier_summary(const FitJobResult& r) {
  const FitReport& rep = r.report();
  const OutlierReport& o = rep.outliers;
  std::string text = "Outliers: " + std::to_string(o.count) + " of " +
                     std::to_string(r.points.cols()) + " points rejected at > " +
                     number_text(kOutlierSigmas) + " σ (σ = " + number_text(o.scale) +
                     " mm, threshold " + number_text(o.threshold) + " mm";
  if (o.count > 0) text += "; largest " + number_text(o.largest) + " mm";
  return text + "); the distances are of the " + std::to_string(rep.error.count) + " points kept.";
}

namespace {

// Every input point's closest-point search (point_distances.h): none is dropped; the counts say how
// many converged from the synchronized start, after the restart, or not at all, and why.
json foot_points_json(const FitReport& rep) {
  const std::size_t n = static_cast<std::size_t>(rep.signed_distance.size());
  json j{{"searched", n},
         {"converged_first", n - std::min(n, rep.restarted + rep.unconverged)},
         {"restarted", rep.restarted},
         {"unconverged", rep.unconverged},
         {"dropped", 0}};
  j["restart"] =
      "a search that hits the iteration limit from the synchronized parameters is restarted from "
      "the closest of a 9 x 9 parameter grid spanning a fifth of the domain around them";
  j["unconverged_reason"] =
      rep.unconverged == 0
          ? json(nullptr)
          : json(
                "the Gauss-Newton foot-point iteration hit its iteration limit from both starts "
                "(e.g. a point near a pole or fold, or far from the surface); the distance of "
                "the closest point it reached is kept in the statistics, not dropped");
  return j;
}

}  // namespace

json fit_report_fields(const FitJobResult& r) {
  const FitReport& rep = r.report();
  json j;
  j["input"] = {{"file", r.input.string()}, {"points", r.points.cols()}, {"dropped", r.dropped}};
  j["method"] = r.method;
  j["reason"] = r.reason;
  if (const ProfileFit* profile = std::get_if<ProfileFit>(&r.fit)) {
    const PolarCurveFit& f = profile->polar;
    j["quadric"] = nullptr;
    j["frame"] = frame_json(r.plane.frame,
                            r.plane.snapped ? "the plane z = const of the input (x, y kept)"
                                            : "best-fit plane of the points (total least squares)");
    j["plane"] = {{"rms_distance_mm", r.plane.rms_distance},
                  {"max_distance_mm", r.plane.max_distance}};
    j["centre"] = vec(r.plane.frame.to_global(Eigen::Vector3d(f.centre.x(), f.centre.y(), 0.0)));
    j["centre_reason"] = f.centre_reason;
    j["closed"] = f.closed;
    j["degrees"] = {{"F", json::array({rep.degree_v})},
                    {"nurbs", json::array({profile->curve.degree()})}};
    j["control_net"] = {{"F", json::array({rep.size_v})},
                        {"nurbs", json::array({profile->curve.size()})}};
  } else {
    const RotationalFit& f = std::get<RotationalFit>(r.fit);
    const FrameEstimate& fr = f.frame();
    j["quadric"] = fr.quadric ? quadric_json(*fr.quadric) : json(nullptr);
    j["frame"] = frame_json(fr.frame, fr.reason);
    json candidates = json::array();
    for (std::size_t i = 0; i < f.frame_candidates.size(); ++i) {
      const FrameCandidate& c = f.frame_candidates[i];
      json e{{"name", c.name}, {"origin", vec(c.origin)}, {"axis", vec(c.axis)}, {"how", c.how}};
      e["rms_mm"] = c.rms >= 0.0 ? json(c.rms) : json(nullptr);
      if (c.rms >= 0.0) {
        e["F"] = c.rotational ? "F(u) alone" : "F(u, v)";
        e["revolution_p_value"] = c.p_value >= 0.0 ? json(c.p_value) : json(nullptr);
        e["coefficients"] = c.coefficients;
        e["points"] = c.points;
      }
      e["chosen"] = static_cast<int>(i) == f.chosen_candidate;
      if (!c.failure.empty()) e["failure"] = c.failure;
      candidates.push_back(std::move(e));
    }
    j["frame_candidates"] = std::move(candidates);
    if (const auto* sphere = std::get_if<SphericalFit>(&f.fit)) {
      const SphericalFit& s = *sphere;
      j["closed"] = s.closed;
      if (s.closed)
        j["seam"] = {{"gap_mm", s.seam.gap},
                     {"normal_angle_deg", s.seam.normal_angle * kDegreesPerRadian}};
      j["poles"] = {{"north", pole_json(s.north, s.north_check, s.north_pole, s.north_cap)},
                    {"south", pole_json(s.south, s.south_check, s.south_pole, s.south_cap)}};
    } else {
      const CylindricalFit& c = std::get<CylindricalFit>(f.fit);
      j["closed"] = c.closed;
      if (c.closed)
        j["seam"] = {{"gap_mm", c.seam.gap},
                     {"normal_angle_deg", c.seam.normal_angle * kDegreesPerRadian}};
      j["height_range_mm"] = json::array({c.base.z_start(), c.base.z_end()});
    }
    j["degrees"] = {{"F", json::array({rep.degree_u, rep.degree_v})},
                    {"nurbs", json::array({rep.nurbs_degree_u, rep.nurbs_degree_v})}};
    j["control_net"] = {{"F", json::array({rep.size_u, rep.size_v})},
                        {"nurbs", json::array({rep.nurbs_size_u, rep.nurbs_size_v})}};
  }
  j["fairness"] = fairness_word(r.fairness);
  if (r.fairness != FairnessOptions::Mode::gcv) j["fairness_weight"] = r.fairness_weight;
  j["fairness_lambda"] = rep.lambda;
  j["base"] = r.base == ArcKind::quartic ? "quartic" : "rqb";
  j["refinements"] = rep.refinements;
  j["control_net_choice"] = net_json(rep.net);
  j["revolution"] = revolution_json(rep.revolution);
  j["error_mm"] = stats(rep.error);
  j["error_mm"]["unconverged_foot_points"] = rep.unconverged;
  j["foot_points"] = foot_points_json(rep);
  j["error_kind"] = "true closest-point distance from each input point to the fitted geometry";
  j["radial_error_mm"] = stats(rep.radial);
  j["deviation_color_limit_mm"] = deviation_color_limit(r);
  if (r.reject_outliers) {
    const OutlierReport& o = rep.outliers;
    j["outliers"] = {{"rejected", o.count},
                     {"threshold_sigma", kOutlierSigmas},
                     {"sigma_mm", o.scale},
                     {"threshold_mm", o.threshold},
                     {"largest_mm", o.largest}};
  }
  j["warnings"] = r.warnings;
  if (r.interrogation) j["interrogation"] = surface_interrogation_json(*r.interrogation);
  if (r.surface_fairing) j["fairing"] = surface_fairing_json(*r.surface_fairing);
  if (const auto* profile = std::get_if<ProfileFit>(&r.fit)) {
    j["interrogation"] = interrogation_json(profile->interrogation);
    if (profile->fairing) j["fairing"] = fairing_json(*profile->fairing);
  }
  return j;
}

json fit_report_json(const FitJobResult& r, const std::vector<std::string>& files) {
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "fit";
  j.update(fit_report_fields(r));
  j["timings_s"] = times_json(r.report().times);
  j["files"] = files;
  return j;
}

std::map<std::string, std::string> render_fit_outputs(const FitJobResult& r) {
  std::map<std::string, std::string> content;
  const ProfileFit* profile = std::get_if<ProfileFit>(&r.fit);
  const std::string stem = profile ? "curve" : "surface";
  const std::string name = r.input.stem().string();
  auto [iges, step] = exchange_headers(r.method + " fit of " + r.input.filename().string());
  iges.file_name = stem + ".igs";
  step.file_name = stem + ".stp";
  IgesWriter igs;
  StepWriter stp(name);
  X3dWriter x3d;
  if (profile) {
    igs.add(profile->curve, "FITTED CURVE");
    stp.add(profile->curve, "fitted curve");
    x3d.add(profile->curve, "curve");
    DxfWriter dxf(DxfOptions{std::max(10, profile->curve.degree()), 1e-6});
    dxf.add(profile->curve, "FITTED_CURVE");
    content["curve.dxf"] = dxf.str();
  } else {
    const RotationalFit& surface = std::get<RotationalFit>(r.fit);
    igs.add(surface.surface(), "FITTED SURFACE");
    stp.add(surface.surface(), "fitted surface");
    x3d.add(surface.surface(), "surface");
    if (const auto* sphere = std::get_if<SphericalFit>(&surface.fit)) {
      const SphericalFit& s = *sphere;
      const std::pair<const std::optional<PoleCap>*, std::string> caps[] = {
          {&s.north_cap, "north"}, {&s.south_cap, "south"}};
      for (const auto& [cap, which] : caps)
        if (*cap) {
          igs.add((*cap)->surface, which + " cap");
          stp.add((*cap)->surface, which + " cap");
          x3d.add((*cap)->surface, which + "_cap");
        }
    }
  }
  content[stem + ".igs"] = igs.str(iges);
  content[stem + ".stp"] = stp.str(step);
  content[stem + ".x3d"] =
      x3d.str("polarform " + r.method + " fit of " + r.input.filename().string());
  const std::string preview = svg_document(fit_preview_figure(r));
  content["preview.svg"] = preview;
  if (profile) {
    content["curvature.svg"] = svg_document(
        profile_curvature_figure(profile->interrogation, "polar angle θ about the centre [deg]",
                                 profile->before_fairing ? &*profile->before_fairing : nullptr));
    content["curvature.csv"] = interrogation_csv(profile->interrogation);
  }
  if (r.surface_fairing)
    content["fairing.svg"] = svg_document(surface_fairing_figure(*r.surface_fairing));
  if (r.interrogation)
    for (const auto& [name, text] :
         interrogation_x3d(*r.interrogation, r.input.filename().string()))
      content[name] = text;
  const std::vector<std::string> files = fit_file_list(content, r.interrogation.has_value());
  const json report = fit_report_json(r, files);
  content["report.json"] = report_json_text(report);
  content["report.html"] = html_report(r, report, preview);
  return content;
}

std::vector<std::string> write_fit_outputs(const FitJobResult& r,
                                           const std::filesystem::path& dir) {
  const std::map<std::string, std::string> content = render_fit_outputs(r);
  const Eigen::VectorXd& d = r.report().signed_distance;
  if (d.size() != r.points.cols())
    throw NumericalError("fit: " + std::to_string(d.size()) + " deviations for " +
                         std::to_string(r.points.cols()) + " points");
  const double limit = deviation_color_limit(r);
  std::vector<std::array<unsigned char, 3>> colors(static_cast<std::size_t>(d.size()));
  std::vector<double> deviation(colors.size());
  for (Eigen::Index k = 0; k < d.size(); ++k) {
    colors[static_cast<std::size_t>(k)] = to_rgb8(diverging_color(d[k], limit));
    deviation[static_cast<std::size_t>(k)] = d[k];
  }
  OutputTransaction outputs(dir);  // deviation.ply with the others: all or nothing
  for (const auto& [name, text] : content) outputs.add(name, text);
  outputs.add("deviation.ply",
              ply_writer(dir / "deviation.ply", r.points, &colors, &deviation, "deviation"));
  if (r.interrogation) add_interrogation_ply(outputs, dir, *r.interrogation);
  outputs.commit();
  return fit_file_list(content, r.interrogation.has_value());
}

}  // namespace polarform
