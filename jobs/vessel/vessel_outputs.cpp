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
#include "export/svg_plot.h"
#include "jobs/report/conversion_report.h"
#include "jobs/report/exchange_headers.h"
#include "jobs/report/output_files.h"
#include "jobs/vessel/vessel_plots.h"
#include "jobs/vessel/vessel_report.h"
#include "polarform_version.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

std::string profile_csv(const VesselSolveStage& r) {
  const VesselSolution& s = r.solution;
  std::vector<std::string> headers = {"theta [deg]", "R [mm]", "dR/dtheta [mm/rad]",
                                      "d2R/dtheta2 [mm/rad^2]", "x [mm]", "z [mm]",
                                      "kappa [1/mm]"};
  if (s.preset) headers.insert(headers.end(), {"preset R [mm]", "preset kappa [1/mm]"});
  CsvWriter csv(headers);
  for (const CurvatureSample& c : s.curvature) {
    std::vector<double> row = {
        c.theta * kDegreesPerRadian, c.R,    c.dR, c.d2R, c.R * std::cos(c.theta),
        c.R * std::sin(c.theta),     c.kappa};
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

// The designed head first, then the standard heads of its depth.
std::vector<const HeadStressSummary*> same_depth_rows(const MinimumStressDesign& m) {
  std::vector<const HeadStressSummary*> rows{&m.stresses};
  for (const HeadStressSummary& h : m.same_depth.references) rows.push_back(&h);
  return rows;
}

std::string micrometres(double mm) { return format_trimmed(mm * 1e3, 4) + " µm"; }

std::string html_report(const VesselJobResult& r, const VesselOutputOptions& o, const json& report,
                        const std::map<std::string, std::string>& svgs) {
  const VesselSolution& s = r.solved.solution;
  const VesselConversionStage& c = r.converted;
  const json& stresses = report["stresses"];
  HtmlReport html("polarform vessel report: " + o.design_name);
  std::vector<std::pair<std::string, std::string>> key;
  if (s.exact) {
    key.emplace_back("head", s.exact->shape.name + ", exact");
  } else if (s.minimum_stress) {
    const json& m = report["minimum_stress"];
    key.emplace_back("head", "minimum peak membrane stress for its depth");
    key.emplace_back("peak membrane stress",
                     format_trimmed(s.minimum_stress->stresses.peak_stress, 4) + " MPa");
    key.emplace_back("below the best standard head of its depth",
                     format_trimmed(m["peak_below_best_standard_pct"].get<double>(), 3) + " %");
    key.emplace_back("iterations", std::to_string(s.minimum_stress->head.iterations));
  } else {
    key.emplace_back("iterations", std::to_string(s.synthesis.iterations));
    key.emplace_back(
        "max |κ residual|",
        number_text(report["synthesis"]["max_abs_residual_per_mm"].get<double>()) + " 1/mm");
    key.emplace_back("max condition violation", format_trimmed(s.synthesis.max_violation, 9));
  }
  key.emplace_back("head depth", format_trimmed(s.depth, 3) + " mm");
  key.emplace_back("tolerance", micrometres(r.solved.project.tolerance));
  key.emplace_back(
      s.exact ? "measured max radial error against the closed form" : "measured max radial error",
      micrometres(c.max_radial_error));
  key.emplace_back("degree", std::to_string(c.profile.degree()));
  key.emplace_back("control points", std::to_string(c.profile.size()));
  key.emplace_back(s.exact ? "conic arcs" : "base-circle arcs", std::to_string(c.arcs));
  key.emplace_back("max membrane stress",
                   format_trimmed(stresses["max_stress_mpa"].get<double>(), 3) + " MPa");
  key.emplace_back(
      "min hoop stress",
      format_trimmed(stresses["head"]["min_hoop_stress_mpa"].get<double>(), 4) + " MPa");
  key.emplace_back("compressive hoop stress", s.stresses.compressive_hoop.empty() ? "none" : "YES");
  if (s.code) {
    key.emplace_back("ASME VIII-1 MAWP", format_trimmed(s.code->mawp, 4) + " MPa");
    key.emplace_back("required thickness, shell",
                     format_trimmed(s.code->shell.required_thickness, 4) + " mm (" +
                         s.code->shell.thickness_formula + ")");
    key.emplace_back("required thickness, head",
                     s.code->head ? format_trimmed(s.code->head->required_thickness, 4) + " mm (" +
                                        s.code->head->thickness_formula + ")"
                                  : s.code->head_note);
    key.emplace_back("wall " + format_trimmed(r.solved.design.thickness, 4) + " mm",
                     s.code->thickness_sufficient ? "sufficient" : "TOO THIN");
  }
  if (s.measures) {
    key.emplace_back("vessel volume", format_trimmed(s.measures->vessel_volume * 1e-6, 6) + " L");
    key.emplace_back("metal weight", format_trimmed(s.measures->weight, 5) + " kg at " +
                                         format_trimmed(s.measures->density, 5) + " kg/m³");
  }
  key.emplace_back("time", format_trimmed(r.seconds.total * 1e3, 1) + " ms");
  html.add_key_figures(key);
  if (!s.warnings.empty()) {
    html.add_heading("Warnings");
    for (const std::string& w : s.warnings) html.add_paragraph(w);
  }
  html.add_heading("Curvature");
  const std::string preset_note =
      s.preset ? "; the preset's curvature dashed, its jumps in orange" : "";
  html.add_svg(svgs.at("curvature.svg"),
               s.exact ? "The exact head's curvature κ(θ), piece by piece: its jumps are the "
                         "head's own."
                       : "Prescribed curvature targets and the synthesised κ(θ)" + preset_note +
                             "; below, the residual at each target.");
  std::vector<std::vector<std::string>> targets;
  for (const TargetResidual& t : s.synthesis.targets)
    targets.push_back({format_trimmed(t.theta * kDegreesPerRadian, 4), number_text(t.target),
                       number_text(t.achieved), number_text(t.residual()),
                       format_trimmed(t.weight, 4)});
  html.add_table({"θ [deg]", "target κ [1/mm]", "achieved κ [1/mm]", "residual [1/mm]", "weight"},
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
  if (s.minimum_stress) {
    html.add_heading("Heads of the same depth");
    html.add_svg(svgs.at("same_depth.svg"),
                 "Hoop and meridional membrane stresses of the minimum-stress head (solid) and the "
                 "standard heads of its depth (dashed), junction to apex.");
    std::vector<std::vector<std::string>> rows;
    for (const HeadStressSummary* h : same_depth_rows(*s.minimum_stress))
      rows.push_back({h->name, format_trimmed(h->peak_stress, 5),
                      format_trimmed(h->peak_theta * kDegreesPerRadian, 4),
                      format_trimmed(h->min_hoop_stress, 5), format_trimmed(h->max_hoop_stress, 5),
                      number_text(h->junction_curvature)});
    html.add_table({"head", "peak |σ| [MPa]", "at θ [deg]", "min σθ [MPa]", "max σθ [MPa]",
                    "junction κ [1/mm]"},
                   rows);
    for (const std::string& m : s.minimum_stress->same_depth.missing) html.add_paragraph(m);
  }
  html.add_heading("Membrane stresses");
  html.add_svg(svgs.at("stress.svg"),
               "Meridional σφ and hoop σθ along the meridian; shaded: compressive hoop stress.");
  if (!s.edge_bending.empty()) {
    html.add_heading("Edge bending");
    html.add_paragraph(
        "Bending at the curvature jumps by thin-shell edge theory (Geckeler's approximation, "
        "Timoshenko & Woinowsky-Krieger §§ 130–134): edge shear Q0 = p r2 |Δκ| / (8β), "
        "β = [3(1 − ν²)]^¼ / √(r2 t), peak moment 0.3224 Q0/β at π/(4β) from the joint, ν = " +
        format_trimmed(r.solved.design.poisson, 3) +
        ". Approximate where the decay length π/β exceeds a piece meeting there.");
    std::vector<std::vector<std::string>> rows;
    for (const EdgeBending& e : s.edge_bending)
      rows.push_back(
          {format_trimmed(e.theta * kDegreesPerRadian, 4), number_text(e.kappa_jump),
           format_trimmed(e.shear, 4), format_trimmed(e.bending_stress, 4),
           format_trimmed(e.max_meridional_stress, 4), format_trimmed(e.hoop_stress_at_joint, 4),
           format_trimmed(e.decay_length, 4) + (e.approximate() ? " (approximate)" : "")});
    html.add_table({"joint θ [deg]", "Δκ [1/mm]", "Q0 [N/mm]", "σ bending [MPa]",
                    "σφ membrane + bending [MPa]", "σθ at joint [MPa]", "π/β [mm]"},
                   rows);
  }
  html.add_heading("NURBS profile");
  html.add_svg(svgs.at("profile.svg"), "The exported profile with its control polygon.");
  if (c.conversion) {
    std::vector<std::vector<std::string>> arcs;
    for (const ArcSummary& a : c.conversion->arcs)
      arcs.push_back({format_trimmed(a.start * kDegreesPerRadian, 4),
                      format_trimmed(a.sweep * kDegreesPerRadian, 4),
                      format_trimmed(a.max_radial_error * 1e3, 4)});
    html.add_table({"arc start θ [deg]", "sweep [deg]", "max radial error [µm]"}, arcs);
  } else {
    html.add_paragraph(
        "The head's circular and elliptic arcs are rational quadratic segments (NURBS Book "
        "§7.5), exact up to rounding; revolved, the head is a (2, 2) surface.");
  }
  html.add_file_list(report["files"].get<std::vector<std::string>>());
  return html.html();
}

}  // namespace

std::map<std::string, std::string> render_vessel_outputs(const VesselJobResult& r,
                                                         const VesselOutputOptions& o) {
  std::map<std::string, std::string> content;
  auto [iges, step] = exchange_headers("vessel " + o.design_name);
  const auto write_iges = [&](const IgesWriter& w, const std::string& name) {
    iges.file_name = name;
    content[name] = w.str(iges);
  };
  const auto write_step = [&](const StepWriter& w, const std::string& name) {
    step.file_name = name;
    content[name] = w.str(step);
  };

  // The profile in the meridian plane y = 0 (the surfaces' frame); the DXF as a drawing (x, y).
  const NurbsCurve3d meridian = in_meridian_plane(r.converted.profile);
  IgesWriter profile_igs;
  profile_igs.add(meridian, "HEAD PROFILE");
  write_iges(profile_igs, "profile.igs");
  StepWriter profile_stp(o.design_name + " profile");
  profile_stp.add(meridian, "head profile");
  write_step(profile_stp, "profile.stp");
  DxfWriter dxf(DxfOptions{std::max(10, r.converted.profile.degree()), 1e-6});
  dxf.add(r.converted.profile, "PROFILE");
  content["profile.dxf"] = dxf.str();

  IgesWriter head_igs;
  head_igs.add(r.converted.surfaces.head, "HEAD");
  write_iges(head_igs, "head.igs");
  StepWriter head_stp(o.design_name + " head");
  head_stp.add(r.converted.surfaces.head, "head");
  write_step(head_stp, "head.stp");
  StepWriter vessel_stp(o.design_name);
  vessel_stp.add(r.converted.surfaces.head, "head");
  vessel_stp.add(r.converted.surfaces.cylinder, "cylinder");
  vessel_stp.add(r.converted.surfaces.far_head, "far head");
  write_step(vessel_stp, "vessel.stp");

  content["profile.csv"] = profile_csv(r.solved);
  content["stress.csv"] = stress_csv(r.solved.solution.stresses);
  std::map<std::string, std::string> svgs = {
      {"curvature.svg", svg_document(curvature_figure(r.solved))},
      {"stress.svg", svg_document(stress_figure(r.solved))},
      {"profile.svg", svg_document(profile_figure(r.solved, &r.converted))}};
  if (r.solved.solution.minimum_stress)
    svgs["same_depth.svg"] = svg_document(same_depth_figure(r.solved));
  content.insert(svgs.begin(), svgs.end());
  const std::vector<std::string> files = report_file_list(content);
  const json report = vessel_report_json(r, files);
  content["report.json"] = report_json_text(report);
  content["report.html"] = html_report(r, o, report, svgs);
  return content;
}

std::vector<std::string> write_vessel_outputs(const VesselJobResult& r,
                                              const std::filesystem::path& dir,
                                              const VesselOutputOptions& o) {
  // Everything is rendered in memory first, so a failure writes nothing.
  const std::map<std::string, std::string> content = render_vessel_outputs(r, o);
  write_files_atomically(dir, content);
  return report_file_list(content);
}

}  // namespace polarform
