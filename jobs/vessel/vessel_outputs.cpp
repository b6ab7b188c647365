#include "jobs/vessel/vessel_outputs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "designers/vessel/polar_curvature.h"
#include "export/atomic_file.h"
#include "export/csv_writer.h"
#include "export/dxf_writer.h"
#include "export/html_report.h"
#include "export/iges_writer.h"
#include "export/step_writer.h"
#include "jobs/report/conversion_report.h"
#include "jobs/vessel/vessel_plots.h"
#include "polarform_version.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

// "mm", "mm/rad" or "mm/rad^2" for a condition named "R(0)", "R'(π)", "R''(0)", …
std::string condition_unit(const std::string& name) {
  const auto order = std::count(name.begin(), name.end(), '\'');
  return order == 0 ? "mm" : order == 1 ? "mm/rad" : "mm/rad^2";
}

json surface_json(const NurbsSurface& s) {
  return {{"degree_u", s.degree_u()}, {"degree_v", s.degree_v()},
          {"control_points_u", s.size_u()}, {"control_points_v", s.size_v()}};
}

// Membrane theory (DESIGN/issue 6): the cylinder's stresses, the head's extremes, the bands.
json stresses_json(const StressProfile& p) {
  json j;
  const StressSample& cylinder = p.samples.front();
  j["cylinder"] = {{"meridional_stress_mpa", cylinder.meridional_stress},
                   {"hoop_stress_mpa", cylinder.hoop_stress}};
  const StressSample *max_phi = nullptr, *max_theta = nullptr, *min_theta = nullptr;
  double max_stress = 0.0;
  for (const StressSample& s : p.samples) {
    max_stress = std::max({max_stress, s.meridional_stress, s.hoop_stress});
    if (s.on_cylinder) continue;
    if (!max_phi || s.meridional_stress > max_phi->meridional_stress) max_phi = &s;
    if (!max_theta || s.hoop_stress > max_theta->hoop_stress) max_theta = &s;
    if (!min_theta || s.hoop_stress < min_theta->hoop_stress) min_theta = &s;
  }
  j["head"] = {{"max_meridional_stress_mpa", max_phi->meridional_stress},
               {"max_meridional_at_deg", max_phi->theta * kDegreesPerRadian},
               {"max_hoop_stress_mpa", max_theta->hoop_stress},
               {"max_hoop_at_deg", max_theta->theta * kDegreesPerRadian},
               {"min_hoop_stress_mpa", min_theta->hoop_stress},
               {"min_hoop_at_deg", min_theta->theta * kDegreesPerRadian}};
  j["max_stress_mpa"] = max_stress;
  j["compressive_hoop"] = !p.compressive_hoop.empty();
  j["compressive_hoop_bands"] = json::array();
  for (const CompressiveBand& b : p.compressive_hoop)
    j["compressive_hoop_bands"].push_back({{"theta_from_deg", b.theta_from * kDegreesPerRadian},
                                           {"theta_to_deg", b.theta_to * kDegreesPerRadian},
                                           {"s_from_mm", b.s_from},
                                           {"s_to_mm", b.s_to},
                                           {"min_hoop_stress_mpa", b.min_hoop_stress}});
  return j;
}

json preset_json(const VesselJobResult& r) {
  const HeadPreset& h = *r.design.preset;
  const PresetComparison& c = *r.solution.preset;
  json j = {{"kind", head_kind_name(h.kind)}, {"name", c.shape.name}};
  if (h.kind == HeadKind::ellipsoidal) j["ratio"] = h.ratio;
  if (h.kind == HeadKind::torispherical) {
    j["crown_mm"] = h.crown;
    j["knuckle_mm"] = h.knuckle;
  }
  j["depth_mm"] = c.shape.depth;
  j["max_deviation_mm"] = c.max_deviation;
  j["deviation_at_deg"] = c.deviation_angle * kDegreesPerRadian;
  j["curvature_jumps"] = json::array();
  for (const CurvatureJump& k : c.shape.jumps)
    j["curvature_jumps"].push_back({{"theta_deg", k.theta * kDegreesPerRadian},
                                    {"kappa_before_per_mm", k.kappa_before},
                                    {"kappa_after_per_mm", k.kappa_after}});
  j["stresses"] = stresses_json(c.stresses);
  return j;
}

json synthesis_json(const VesselJobResult& r) {
  const SynthesisResult& s = r.solution.synthesis;
  const SynthesisSettings& set = r.design.synthesis;
  double max_residual = 0.0, sum_squares = 0.0;
  for (const TargetResidual& t : s.targets) {
    max_residual = std::max(max_residual, std::abs(t.residual()));
    sum_squares += t.residual() * t.residual();
  }
  return {{"degree", set.degree},
          {"ordinates", set.ordinates},
          {"smoothing", set.smoothing},
          {"symmetric", set.symmetric},
          {"unknowns", s.unknowns},
          {"free_parameters", s.free_parameters},
          {"targets_from_preset", r.design.targets.empty()},
          {"target_count", s.targets.size()},
          {"iterations", s.iterations},
          {"max_iterations", set.max_iterations},
          {"termination", s.termination},
          {"objective", s.objective},
          {"fit_term", s.fit_term},
          {"stationarity", s.stationarity},
          {"max_abs_residual_per_mm", max_residual},
          {"rms_residual_per_mm", std::sqrt(sum_squares / s.targets.size())},
          {"max_violation", s.max_violation},
          {"min_radius_mm", s.min_radius},
          {"min_radius_at_deg", s.min_radius_angle * kDegreesPerRadian}};
}

std::string profile_csv(const VesselJobResult& r) {
  const VesselSolution& s = r.solution;
  std::vector<std::string> headers = {"theta [deg]", "R [mm]", "dR/dtheta [mm/rad]",
                                      "d2R/dtheta2 [mm/rad^2]", "x [mm]", "z [mm]",
                                      "kappa [1/mm]"};
  if (s.preset) headers.insert(headers.end(), {"preset R [mm]", "preset kappa [1/mm]"});
  CsvWriter csv(headers);
  for (const CurvatureSample& c : s.curvature) {
    double d[3];
    s.profile.derivatives(c.theta, 2, d);
    std::vector<double> row = {
        c.theta * kDegreesPerRadian, d[0],   d[1], d[2], d[0] * std::cos(c.theta),
        d[0] * std::sin(c.theta),    c.kappa};
    if (s.preset) {
      double e[3];
      s.preset->shape.profile.derivatives(c.theta, 2, e);
      row.insert(row.end(), {e[0], polar_curvature(e[0], e[1], e[2])});
    }
    csv.row(row);
  }
  return csv.str();
}

std::string stress_csv(const StressProfile& p) {
  CsvWriter csv({"s [mm]", "theta [deg]", "rho [mm]", "z [mm]", "kappa1 [1/mm]", "r2 [mm]",
                 "N_phi [N/mm]", "N_theta [N/mm]", "sigma_phi [MPa]", "sigma_theta [MPa]",
                 "on cylinder [1/0]"});
  for (const StressSample& k : p.samples)
    csv.row({k.s, k.theta * kDegreesPerRadian, k.rho, k.z, k.radii.kappa1, k.radii.r2,
             k.forces.meridional, k.forces.hoop, k.meridional_stress, k.hoop_stress,
             k.on_cylinder ? 1.0 : 0.0});
  return csv.str();
}

std::string micrometres(double mm) { return format_trimmed(mm * 1e3, 4) + " µm"; }

std::string html_report(const VesselJobResult& r, const VesselOutputOptions& o, const json& report,
                        const std::map<std::string, std::string>& svgs) {
  const VesselSolution& s = r.solution;
  const PolarConversion& c = r.conversion;
  const json& stresses = report["stresses"];
  HtmlReport html("polarform vessel report: " + o.design_name);
  html.add_key_figures(
      {{"iterations", std::to_string(s.synthesis.iterations)},
       {"max |κ residual|",
        format_trimmed(report["synthesis"]["max_abs_residual_per_mm"].get<double>() * 1e3, 6) +
            " 1/m"},
       {"max condition violation", format_trimmed(s.synthesis.max_violation, 9)},
       {"head depth", format_trimmed(s.depth, 3) + " mm"},
       {"tolerance", micrometres(c.tolerance)},
       {"measured max radial error", micrometres(c.max_radial_error)},
       {"degree", std::to_string(c.curve.degree())},
       {"control points", std::to_string(c.curve.size())},
       {"base-circle arcs", std::to_string(c.arcs.size())},
       {"max membrane stress",
        format_trimmed(stresses["max_stress_mpa"].get<double>(), 3) + " MPa"},
       {"compressive hoop stress", s.stresses.compressive_hoop.empty() ? "none" : "YES"},
       {"time", format_trimmed(r.seconds.total * 1e3, 1) + " ms"}});
  if (!s.warnings.empty()) {
    html.add_heading("Warnings");
    for (const std::string& w : s.warnings) html.add_paragraph(w);
  }
  html.add_heading("Curvature");
  const std::string preset_note =
      s.preset ? "; the preset's curvature dashed, its jumps in orange" : "";
  html.add_svg(svgs.at("curvature.svg"), "Prescribed curvature targets and the synthesised κ(θ)" +
                                             preset_note + "; below, the residual at each target.");
  std::vector<std::vector<std::string>> targets;
  for (const TargetResidual& t : s.synthesis.targets)
    targets.push_back({format_trimmed(t.theta * kDegreesPerRadian, 4),
                       format_trimmed(t.target * 1e3, 6), format_trimmed(t.achieved * 1e3, 6),
                       format_trimmed(t.residual() * 1e3, 6), format_trimmed(t.weight, 4)});
  html.add_table({"θ [deg]", "target κ [1/m]", "achieved κ [1/m]", "residual [1/m]", "weight"},
                 targets);
  std::vector<std::vector<std::string>> conditions;
  for (const ConditionViolation& v : s.synthesis.conditions)
    conditions.push_back({v.name, format_trimmed(v.prescribed, 6), format_trimmed(v.achieved, 9),
                          format_trimmed(v.violation(), 12), condition_unit(v.name)});
  if (!conditions.empty())
    html.add_table({"end condition", "prescribed", "achieved", "violation", "unit"}, conditions);
  if (s.preset)
    html.add_paragraph("Against the " + s.preset->shape.name + " head: max |ΔR| " +
                       format_trimmed(s.preset->max_deviation, 4) + " mm at θ = " +
                       format_trimmed(s.preset->deviation_angle * kDegreesPerRadian, 3) +
                       "°; preset depth " + format_trimmed(s.preset->shape.depth, 3) + " mm.");
  html.add_heading("Membrane stresses");
  html.add_svg(svgs.at("stress.svg"),
               "Meridional σφ and hoop σθ along the meridian; shaded: compressive hoop stress.");
  html.add_heading("NURBS profile");
  html.add_svg(svgs.at("profile.svg"), "The exported profile with its control polygon.");
  std::vector<std::vector<std::string>> arcs;
  for (const ArcSummary& a : c.arcs)
    arcs.push_back({format_trimmed(a.start * kDegreesPerRadian, 4),
                    format_trimmed(a.sweep * kDegreesPerRadian, 4),
                    format_trimmed(a.max_radial_error * 1e3, 4)});
  html.add_table({"arc start [deg]", "sweep [deg]", "max radial error [µm]"}, arcs);
  html.add_file_list(report["files"].get<std::vector<std::string>>());
  return html.html();
}

}  // namespace

json vessel_report_json(const VesselJobResult& r, const std::vector<std::string>& files) {
  const VesselDesign& d = r.design;
  const VesselSolution& s = r.solution;
  const PolarConversion& c = r.conversion;
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "vessel";
  j["vessel"] = {{"radius_mm", d.radius}, {"length_mm", d.length},
                 {"thickness_mm", d.thickness}, {"pressure_mpa", d.pressure}};
  j["synthesis"] = synthesis_json(r);
  j["targets"] = json::array();
  for (const TargetResidual& t : s.synthesis.targets)
    j["targets"].push_back({{"theta_deg", t.theta * kDegreesPerRadian},
                            {"target_per_mm", t.target},
                            {"achieved_per_mm", t.achieved},
                            {"residual_per_mm", t.residual()},
                            {"weight", t.weight}});
  j["conditions"] = json::array();
  for (const ConditionViolation& v : s.synthesis.conditions)
    j["conditions"].push_back({{"name", v.name}, {"unit", condition_unit(v.name)},
                               {"prescribed", v.prescribed}, {"achieved", v.achieved},
                               {"violation", v.violation()}});
  j["head"] = {{"depth_mm", s.depth},
               {"junction_radius_mm", s.junction_radius},
               {"junction_curvature_per_mm", s.junction_curvature},
               {"junction_slope_deg", s.junction_slope * kDegreesPerRadian},
               {"apex_slope_deg", s.apex_slope * kDegreesPerRadian}};
  // Conversion: the same field names as the cam report.
  add_conversion_fields(j, c, c.curve.degree(), c.curve.size(), c.curve.knots().size());
  j["surfaces"] = {{"head", surface_json(r.surfaces.head)},
                   {"cylinder", surface_json(r.surfaces.cylinder)},
                   {"far_head", surface_json(r.surfaces.far_head)}};
  j["stresses"] = stresses_json(s.stresses);
  j["preset"] = s.preset ? preset_json(r) : json(nullptr);
  j["warnings"] = s.warnings;
  j["timings"] = {{"solve_s", r.seconds.solve}, {"convert_s", r.seconds.convert},
                  {"revolve_s", r.seconds.revolve}, {"total_s", r.seconds.total}};
  j["files"] = files;
  return j;
}

std::vector<std::string> write_vessel_outputs(const VesselJobResult& r,
                                              const std::filesystem::path& dir,
                                              const VesselOutputOptions& o) {
  // Everything is rendered in memory first, so a failure writes nothing.
  std::map<std::string, std::string> content;
  IgesHeader iges;
  iges.description = "polarform " + std::string(POLARFORM_VERSION) + " vessel " + o.design_name;
  StepHeader step;
  step.description = iges.description;
  const auto write_iges = [&](const IgesWriter& w, const std::string& name) {
    iges.file_name = name;
    content[name] = w.str(iges);
  };
  const auto write_step = [&](const StepWriter& w, const std::string& name) {
    step.file_name = name;
    content[name] = w.str(step);
  };

  // The profile in the meridian plane y = 0 (the surfaces' frame); the DXF as a drawing (x, y).
  const NurbsCurve3d meridian = in_meridian_plane(r.conversion.curve);
  IgesWriter profile_igs;
  profile_igs.add(meridian, "HEAD PROFILE");
  write_iges(profile_igs, "profile.igs");
  StepWriter profile_stp(o.design_name + " profile");
  profile_stp.add(meridian, "head profile");
  write_step(profile_stp, "profile.stp");
  DxfWriter dxf(DxfOptions{std::max(10, r.conversion.curve.degree()), 1e-6});
  dxf.add(r.conversion.curve, "PROFILE");
  content["profile.dxf"] = dxf.str();

  IgesWriter head_igs;
  head_igs.add(r.surfaces.head, "HEAD");
  write_iges(head_igs, "head.igs");
  StepWriter head_stp(o.design_name + " head");
  head_stp.add(r.surfaces.head, "head");
  write_step(head_stp, "head.stp");
  StepWriter vessel_stp(o.design_name);
  vessel_stp.add(r.surfaces.head, "head");
  vessel_stp.add(r.surfaces.cylinder, "cylinder");
  vessel_stp.add(r.surfaces.far_head, "far head");
  write_step(vessel_stp, "vessel.stp");

  content["profile.csv"] = profile_csv(r);
  content["stress.csv"] = stress_csv(r.solution.stresses);
  const std::map<std::string, std::string> svgs = {{"curvature.svg", curvature_figure(r).svg()},
                                                   {"stress.svg", stress_figure(r).svg()},
                                                   {"profile.svg", profile_figure(r).svg()}};
  content.insert(svgs.begin(), svgs.end());
  std::vector<std::string> files;
  for (const auto& [name, text] : content) files.push_back(name);
  files.push_back("report.json");
  files.push_back("report.html");
  const json report = vessel_report_json(r, files);
  content["report.json"] = report.dump(2) + "\n";
  content["report.html"] = html_report(r, o, report, svgs);

  write_files_atomically(dir, content);
  return files;
}

}  // namespace polarform
