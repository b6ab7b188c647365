#include "jobs/vessel/vessel_report.h"

#include <algorithm>
#include <cmath>

#include "jobs/report/conversion_report.h"
#include "polarform_version.h"
#include "src/units.h"

namespace polarform {

// "mm", "mm/rad" or "mm/rad^2" for a condition named "R(0)", "R'(π)", "R''(0)", …
std::string condition_unit(const std::string& name) {
  const auto order = std::count(name.begin(), name.end(), '\'');
  if (name == "V") return "mm^3";
  return order == 0 ? "mm" : order == 1 ? "mm/rad" : "mm/rad^2";
}

namespace {

using json = nlohmann::ordered_json;

json surface_json(const NurbsSurface& s) {
  return {{"degree_u", s.degree_u()},
          {"degree_v", s.degree_v()},
          {"control_points_u", s.size_u()},
          {"control_points_v", s.size_v()}};
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

// A standard head: kind, its parameters, name and depth, and where its curvature jumps.
json standard_head_json(const HeadPreset& h, const HeadShape& shape) {
  json j = {{"kind", head_kind_name(h.kind)}, {"name", shape.name}};
  if (h.kind == HeadKind::ellipsoidal) j["ratio"] = h.ratio;
  if (h.kind == HeadKind::torispherical) {
    j["crown_mm"] = h.crown;
    j["knuckle_mm"] = h.knuckle;
  }
  if (h.kind == HeadKind::conical) {
    j["half_angle_deg"] = h.half_angle * kDegreesPerRadian;
    j["knuckle_mm"] = h.knuckle;
  }
  if (h.kind == HeadKind::flat) j["knuckle_mm"] = h.knuckle;
  j["depth_mm"] = shape.depth;
  j["curvature_jumps"] = json::array();
  for (const CurvatureJump& k : shape.jumps)
    j["curvature_jumps"].push_back({{"theta_deg", k.theta * kDegreesPerRadian},
                                    {"kappa_before_per_mm", k.kappa_before},
                                    {"kappa_after_per_mm", k.kappa_after}});
  return j;
}

json preset_json(const VesselSolveStage& r) {
  const PresetComparison& c = *r.solution.preset;
  json j = standard_head_json(*r.design.preset, c.shape);
  j["max_deviation_mm"] = c.max_deviation;
  j["deviation_at_deg"] = c.deviation_angle * kDegreesPerRadian;
  j["stresses"] = stresses_json(c.stresses);
  return j;
}

// "theta", "s", "phi": the project attribute a target's place is given by.
const char* target_place_name(TargetPlace place) {
  return place == TargetPlace::arc_length       ? "s"
         : place == TargetPlace::meridian_angle ? "phi"
                                                : "theta";
}

json synthesis_json(const VesselSolveStage& r) {
  const SynthesisResult& s = r.solution.synthesis;
  const SynthesisSettings& set = r.design.synthesis;
  double max_residual = 0.0, sum_squares = 0.0;
  for (const TargetResidual& t : s.targets) {
    max_residual = std::max(max_residual, std::abs(t.residual()));
    sum_squares += t.residual() * t.residual();
  }
  const SmoothingChoice& c = r.solution.smoothing;
  return {{"degree", set.degree},
          {"ordinates", set.ordinates},
          {"smoothing", s.smoothing},
          {"smoothing_choice",
           {{"rule", smoothing_rule_name(c.rule)},
            {"trials", c.trials},
            {"met", c.met},
            {"kappa_tolerance_per_mm",
             c.rule == SmoothingRule::tolerance ? json(set.kappa_tolerance) : json(nullptr)},
            {"target_turning_points", c.target_turning_points},
            {"turning_points", c.turning_points}}},
          {"placement_rounds", r.solution.placement_rounds},
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

json head_stresses_json(const HeadStressSummary& h) {
  return {{"name", h.name},
          {"depth_mm", h.depth},
          {"peak_stress_mpa", h.peak_stress},
          {"peak_at_deg", h.peak_theta * kDegreesPerRadian},
          {"max_hoop_stress_mpa", h.max_hoop_stress},
          {"min_hoop_stress_mpa", h.min_hoop_stress},
          {"max_meridional_stress_mpa", h.max_meridional_stress},
          {"junction_curvature_per_mm", h.junction_curvature}};
}

// The minimum-stress head (stress_optimal_head.h) and the standard heads of its depth.
json minimum_stress_json(const VesselDesign& d, const MinimumStressDesign& m) {
  const StressOptimalSettings& settings = m.settings;
  json same_depth = json::array();
  double best = 0.0;
  for (const HeadStressSummary& h : m.same_depth.references) {
    same_depth.push_back(head_stresses_json(h));
    best = same_depth.size() == 1 ? h.peak_stress : std::min(best, h.peak_stress);
  }
  return {{"degree", settings.degree},
          {"ordinates", settings.ordinates},
          {"samples", settings.samples},
          {"junction_curvature_per_mm", d.junction_kappa ? json(*d.junction_kappa) : json(nullptr)},
          {"iterations", m.head.iterations},
          {"termination", m.head.termination},
          {"sampled_peak_stress_mpa", m.head.peak_radius * d.pressure / d.thickness},
          {"head", head_stresses_json(m.stresses)},
          {"same_depth", same_depth},
          {"same_depth_missing", m.same_depth.missing},
          {"peak_below_best_standard_pct", 100 * (1 - m.stresses.peak_stress / best)}};
}

json edge_bending_json(const std::vector<EdgeBending>& edges) {
  json out = json::array();
  for (const EdgeBending& e : edges)
    out.push_back({{"theta_deg", e.theta * kDegreesPerRadian},
                   {"r2_mm", e.r2},
                   {"kappa_jump_per_mm", e.kappa_jump},
                   {"beta_per_mm", e.beta},
                   {"shear_n_per_mm", e.shear},
                   {"max_moment_n", e.max_moment},
                   {"max_moment_offset_mm", e.max_moment_offset},
                   {"bending_stress_mpa", e.bending_stress},
                   {"hoop_bending_stress_mpa", e.hoop_bending_stress},
                   {"meridional_membrane_stress_mpa", e.meridional_membrane_stress},
                   {"hoop_stress_at_joint_mpa", e.hoop_stress_at_joint},
                   {"max_meridional_stress_mpa", e.max_meridional_stress},
                   {"decay_length_mm", e.decay_length},
                   {"shorter_piece_mm", e.shorter_piece},
                   {"approximate", e.approximate()}});
  return out;
}

json code_check_json(const CodeCheck& c) {
  return {{"required_thickness_mm", c.required_thickness},
          {"thickness_formula", c.thickness_formula},
          {"mawp_mpa", c.mawp},
          {"mawp_formula", c.mawp_formula},
          {"warnings", c.warnings}};
}

// ASME VIII-1 on the design's wall (vessel_code_check.h).
json code_json(const VesselDesign& d, const VesselCodeCheck& c) {
  return {{"standard", "ASME BPVC Section VIII Division 1, internal pressure, inside dimensions"},
          {"allowable_stress_mpa", d.code->allowable_stress},
          {"joint_efficiency", d.code->joint_efficiency},
          {"corrosion_allowance_mm", d.code->corrosion_allowance},
          {"shell", code_check_json(c.shell)},
          {"head", c.head ? code_check_json(*c.head) : json(nullptr)},
          {"head_note", c.head ? json(nullptr) : json(c.head_note)},
          {"mawp_mpa", c.mawp},
          {"thickness_sufficient", c.thickness_sufficient}};
}

json measures_json(const VesselMeasures& m) {
  return {{"head_volume_mm3", m.head_volume},
          {"head_area_mm2", m.head_area},
          {"straight_flange_mm", m.straight_flange},
          {"head_metal_volume_mm3", m.head_metal_volume},
          {"head_weight_kg", m.head_weight},
          {"vessel_volume_mm3", m.vessel_volume},
          {"metal_volume_mm3", m.metal_volume},
          {"density_kg_per_m3", m.density},
          {"weight_kg", m.weight}};
}

}  // namespace

json vessel_report_fields(const VesselSolveStage& r, const VesselConversionStage* converted) {
  const VesselDesign& d = r.design;
  const VesselSolution& s = r.solution;
  json j;
  j["vessel"] = {{"radius_mm", d.radius},
                 {"length_mm", d.length},
                 {"thickness_mm", d.thickness},
                 {"pressure_mpa", d.pressure}};
  j["synthesis"] = d.head_design == HeadDesign::curvature ? synthesis_json(r) : json(nullptr);
  j["minimum_stress"] =
      s.minimum_stress ? minimum_stress_json(d, *s.minimum_stress) : json(nullptr);
  j["targets"] = json::array();
  for (const TargetResidual& t : s.synthesis.targets)
    j["targets"].push_back(
        {{"place", target_place_name(t.place)},
         {"s_mm", t.place == TargetPlace::arc_length ? json(t.position) : json(nullptr)},
         {"phi_deg", t.place == TargetPlace::meridian_angle ? json(t.position * kDegreesPerRadian)
                                                            : json(nullptr)},
         {"theta_deg", t.theta * kDegreesPerRadian},
         {"target_per_mm", t.target},
         {"achieved_per_mm", t.achieved},
         {"residual_per_mm", t.residual()},
         {"weight", t.weight}});
  j["conditions"] = json::array();
  for (const ConditionViolation& v : s.synthesis.conditions)
    j["conditions"].push_back({{"name", v.name},
                               {"unit", condition_unit(v.name)},
                               {"prescribed", v.prescribed},
                               {"achieved", v.achieved},
                               {"violation", v.violation()}});
  j["head"] = {
      {"design", head_design_name(d.head_design)},
      {"standard", s.exact ? standard_head_json(*d.preset, s.exact->shape) : json(nullptr)},
      {"depth_mm", s.depth},
      {"junction_radius_mm", s.junction_radius},
      {"junction_curvature_per_mm", s.junction_curvature},
      {"junction_slope_deg", s.junction_slope * kDegreesPerRadian},
      {"apex_slope_deg", s.apex_slope * kDegreesPerRadian}};
  if (converted && converted->conversion) {  // the same field names as the cam report
    const PolarConversion& c = *converted->conversion;
    add_conversion_fields(j, c, c.curve.degree(), c.curve.size(), c.curve.knots().size());
  } else if (converted) {  // an exact head: its own arcs, measured against the closed form
    const NurbsCurve2d& c = converted->profile;
    j["tolerance_mm"] = r.project.tolerance;
    j["arcs"] = converted->arcs;
    j["degree"] = c.degree();
    j["control_points"] = c.size();
    j["knot_count"] = c.knots().size();
    j["max_radial_error_mm"] = converted->max_radial_error;
  }
  if (converted) {
    const VesselSurfaces& v = converted->surfaces;
    j["surfaces"] = {{"head", surface_json(v.head)},
                     {"cylinder", surface_json(v.cylinder)},
                     {"far_head", surface_json(v.far_head)}};
  }
  j["stresses"] = stresses_json(s.stresses);
  j["edge_bending"] = edge_bending_json(s.edge_bending);
  j["code"] = s.code ? code_json(d, *s.code) : json(nullptr);
  j["measures"] = s.measures ? measures_json(*s.measures) : json(nullptr);
  j["flat_plate"] =
      s.flat_plate
          ? json{{"plate_radius_mm", s.flat_plate->plate_radius},
                 {"clamped_edge_stress_mpa", s.flat_plate->clamped_edge},
                 {"clamped_centre_stress_mpa", s.flat_plate->clamped_centre},
                 {"simply_supported_centre_stress_mpa", s.flat_plate->simply_supported_centre}}
          : json(nullptr);
  j["design_measures"] = s.measures_of_design
                             ? json{{"head_volume_mm3", s.measures_of_design->volume},
                                    {"head_area_mm2", s.measures_of_design->area}}
                             : json(nullptr);
  j["preset"] = s.preset ? preset_json(r) : json(nullptr);
  j["warnings"] = s.warnings;
  return j;
}

json vessel_report_json(const VesselJobResult& r, const std::vector<std::string>& files) {
  json j;
  j["polarform_version"] = POLARFORM_VERSION;
  j["command"] = "vessel";
  j.update(vessel_report_fields(r.solved, &r.converted));
  j["timings"] = {{"solve_s", r.seconds.solve},
                  {"convert_s", r.seconds.convert},
                  {"revolve_s", r.seconds.revolve},
                  {"total_s", r.seconds.total}};
  j["files"] = files;
  return j;
}

}  // namespace polarform
