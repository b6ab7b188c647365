#include "ui/studio/vessel_workspace.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "export/atomic_file.h"
#include "jobs/report/report_lines.h"
#include "jobs/vessel/vessel_outputs.h"
#include "jobs/vessel/vessel_plots.h"
#include "jobs/vessel/vessel_report.h"
#include "src/number_text.h"
#include "src/units.h"
#include "ui/studio/colors.h"
#include "ui/studio/document_kind.h"
#include "ui/studio/guarded.h"
#include "ui/studio/splitter.h"
#include "ui/studio/template_picker.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

constexpr float kSurfaceRgb[3] = {0.62f, 0.68f, 0.78f};
constexpr float kHeadRgb[3] = {0.85f, 0.62f, 0.38f};

// The vessel job's stages for the edited project: the solve, then the conversion — whose failure
// is kept as a message, so the solve still shows — with the report's fields and the figures.
VesselRun run_stages(const VesselProject& project) {
  VesselRun run{
      solve_vessel_head(project), std::nullopt, {}, {}, Figure(), Figure(), Figure(), std::nullopt};
  try {
    run.converted = convert_vessel_head(run.solved);
  } catch (...) {
    run.conversion_error = failure_text("conversion", std::current_exception());
  }
  const VesselConversionStage* converted = run.converted ? &*run.converted : nullptr;
  run.fields = vessel_report_fields(run.solved, converted);
  run.meridian = profile_figure(run.solved, converted);
  run.curvature = curvature_figure(run.solved);
  run.stresses = stress_figure(run.solved);
  if (run.solved.solution.minimum_stress) run.same_depth = same_depth_figure(run.solved);
  return run;
}

// A number of the report's fields, as text.
std::string field(const nlohmann::ordered_json& fields, const char* group, const char* name) {
  const auto& v = fields.at(group).at(name);
  return v.is_number() ? number_text(v.get<double>()) : v.dump();
}

}  // namespace

VesselWorkspace::VesselWorkspace(StudioContext& context) : Workspace(context) {}

bool VesselWorkspace::accepts(const std::filesystem::path& file) const {
  try {
    return document_kind(file) == WorkspaceKind::vessel;
  } catch (const std::exception&) {
    return false;
  }
}

bool VesselWorkspace::open(const std::filesystem::path& file, bool as_template) {
  return guarded(log(), "Open " + file.filename().string(), [&] {
    std::vector<std::string> warnings;
    VesselProject project = read_vessel_project(file, warnings);
    for (const auto& w : warnings) log().warning(w);
    document_.replace(std::move(project), as_template ? std::filesystem::path() : file,
                      as_template ? file.stem().string() + " (new)" : file.filename().string());
    results_.reset();
    requested_.reset();
    error_.clear();
    has_document_ = true;
    log().info(as_template ? "New vessel from template " + file.filename().string()
                           : "Opened " + file.string());
  });
}

bool VesselWorkspace::save(const std::filesystem::path& file) {
  return guarded(log(), "Save " + file.filename().string(), [&] {
    write_vessel_project(document_.current(), file);
    document_.saved_as(file);
    log().info("Saved " + file.string());
  });
}

void VesselWorkspace::update() {
  if (auto outcome = task_.poll()) {
    solve_seconds_ = outcome->seconds;
    if (outcome->value) {
      results_ = std::move(*outcome->value);
      error_.clear();
      scene_dirty_ = true;
      for (const auto& w : results_->solved.solution.warnings) log().warning("Vessel: " + w);
      if (!results_->conversion_error.empty())
        log().warning("Vessel " + results_->conversion_error);
    } else if (outcome->error) {
      error_ = failure_text("Vessel synthesis", outcome->error);
      log().error(error_);
    }
  }
  if (!has_document_) return;
  const VesselProject& current = document_.current();
  if (!requested_ || !(*requested_ == current)) {
    requested_ = current;
    task_.start([project = current](TaskControl&) { return run_stages(project); });
  }
}

void VesselWorkspace::draw() {
  if (!has_document_) {
    if (const auto chosen = draw_template_picker("Start a vessel head from a template:",
                                                 context_.examples / "vessels"))
      open(*chosen, true);
    return;
  }
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  float& left_fraction = layout("vessel.left", 0.3f);
  const float left = split_size(left_fraction, avail.x, ImGui::GetFontSize() * 12);
  ImGui::BeginChild("editor", ImVec2(left, avail.y), true);
  draw_editor();
  ImGui::EndChild();
  ImGui::SameLine(0, 0);
  vertical_splitter("vessel split", left_fraction, avail.x);
  ImGui::SameLine(0, 0);
  ImGui::BeginChild("views", ImVec2(0, avail.y), false,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  draw_views();
  ImGui::EndChild();
  document_.settle(ImGui::IsAnyItemActive());
}

void VesselWorkspace::draw_editor() {
  VesselProject& project = document_.edit();
  design_panel_.draw(project);
  section("Curvature targets");
  curvature_table_.draw(project.curvatures);
  draw_summary();
}

void VesselWorkspace::draw_summary() {
  section("Head result");
  if (task_.busy()) ImGui::TextColored(ImVec4(0.1f, 0.4f, 0.8f, 1), "solving…");
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, color::error);
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
    if (results_) ImGui::TextDisabled("Showing the last design that could be solved.");
  }
  if (!results_) return;
  // The numbers of report.json, from the job's report builder.
  const nlohmann::ordered_json& f = results_->fields;
  if (const auto& exact = results_->solved.solution.exact) {
    ImGui::Text("%s, exact: rational quadratic arcs, no synthesis", exact->shape.name.c_str());
    ImGui::Text("depth %s mm", field(f, "head", "depth_mm").c_str());
  } else if (results_->solved.solution.minimum_stress) {
    const nlohmann::ordered_json& m = f.at("minimum_stress");
    ImGui::Text("minimum peak stress for depth %s mm", field(f, "head", "depth_mm").c_str());
    ImGui::Text("NLopt: %s evaluations, %s (%s s)", m.at("iterations").dump().c_str(),
                m.at("termination").get<std::string>().c_str(),
                number_text(solve_seconds_).c_str());
    ImGui::Text("peak |σ| %s MPa",
                number_text(m.at("head").at("peak_stress_mpa").get<double>()).c_str());
    for (const auto& h : m.at("same_depth"))
      ImGui::BulletText("%s: %s MPa", h.at("name").get<std::string>().c_str(),
                        number_text(h.at("peak_stress_mpa").get<double>()).c_str());
    ImGui::Text("%s %% below the best standard head of this depth",
                number_text(m.at("peak_below_best_standard_pct").get<double>()).c_str());
  } else {
    const SynthesisResult& s = results_->solved.solution.synthesis;
    ImGui::Text("%d targets, %d unknowns, %d free parameters", static_cast<int>(s.targets.size()),
                s.unknowns, s.free_parameters);
    ImGui::Text("NLopt: %d evaluations, %s (%s s)", s.iterations, s.termination.c_str(),
                number_text(solve_seconds_).c_str());
    ImGui::Text("max |κ − κₖ| = %s 1/mm, objective %s",
                field(f, "synthesis", "max_abs_residual_per_mm").c_str(),
                field(f, "synthesis", "objective").c_str());
    ImGui::Text("stationarity %s, max condition violation %s",
                field(f, "synthesis", "stationarity").c_str(),
                field(f, "synthesis", "max_violation").c_str());
    ImGui::Text("depth %s mm, smallest R %s mm at %s°", field(f, "head", "depth_mm").c_str(),
                field(f, "synthesis", "min_radius_mm").c_str(),
                field(f, "synthesis", "min_radius_at_deg").c_str());
    const nlohmann::ordered_json& choice = f.at("synthesis").at("smoothing_choice");
    ImGui::Text("smoothing λ %s (%s, %s trials%s); targets placed in %s rounds",
                field(f, "synthesis", "smoothing").c_str(),
                choice.at("rule").get<std::string>().c_str(), choice.at("trials").dump().c_str(),
                choice.at("met").get<bool>() ? "" : ", rule not met",
                field(f, "synthesis", "placement_rounds").c_str());
  }
  if (!f.at("design_measures").is_null())
    ImGui::Text("head volume %s mm³, inner area %s mm²",
                field(f, "design_measures", "head_volume_mm3").c_str(),
                field(f, "design_measures", "head_area_mm2").c_str());
  if (!f.at("flat_plate").is_null())
    ImGui::TextWrapped(
        "flat plate (radius %s mm) bends: %s MPa at its edge if clamped, %s MPa at "
        "its centre if simply supported",
        field(f, "flat_plate", "plate_radius_mm").c_str(),
        field(f, "flat_plate", "clamped_edge_stress_mpa").c_str(),
        field(f, "flat_plate", "simply_supported_centre_stress_mpa").c_str());
  ImGui::Text("junction: κ = %s 1/mm, slope %s°",
              field(f, "head", "junction_curvature_per_mm").c_str(),
              field(f, "head", "junction_slope_deg").c_str());
  ImGui::Text("max membrane stress %s MPa",
              number_text(f.at("stresses").at("max_stress_mpa").get<double>()).c_str());
  if (results_->converted) {
    const VesselConversionStage& c = *results_->converted;
    const double tolerance = results_->solved.project.tolerance;
    ImGui::Text("NURBS: %d arcs, degree %d, %d control points, max radial error %s µm %s %s µm",
                c.arcs, c.profile.degree(), c.profile.size(),
                number_text(to_micrometres(c.max_radial_error)).c_str(),
                c.max_radial_error <= tolerance ? "≤" : ">",
                number_text(to_micrometres(tolerance)).c_str());
  } else if (!results_->conversion_error.empty()) {
    ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "%s", results_->conversion_error.c_str());
  }
}

void VesselWorkspace::draw_views() {
  if (!results_) {
    ImGui::TextDisabled(
        task_.busy() ? "Solving…" : "The design could not be solved; see the message on the left.");
    return;
  }
  if (scene_dirty_) rebuild_scene();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const ImVec2 cell((avail.x - spacing) * 0.5f, (avail.y - ImGui::GetStyle().ItemSpacing.y) * 0.5f);
  ImGui::BeginGroup();
  draw_figure("meridian", results_->meridian, meridian_view_, cell);
  ImGui::EndGroup();
  ImGui::SameLine();
  ImGui::BeginGroup();
  if (results_->converted) {
    ImGui::Checkbox("control net", &scene_.visible(SceneLayer::net));
    scene_.draw(ImVec2(cell.x, cell.y - ImGui::GetFrameHeightWithSpacing()));
  } else {
    ImGui::TextDisabled("No surfaces: %s", results_->conversion_error.c_str());
  }
  ImGui::EndGroup();
  ImGui::BeginGroup();
  draw_figure("curvature", results_->curvature, curvature_view_, cell);
  ImGui::EndGroup();
  ImGui::SameLine();
  ImGui::BeginGroup();
  if (results_->same_depth) {
    ImGui::Checkbox("heads of the same depth", &show_same_depth_);
    const ImVec2 rest(cell.x, cell.y - ImGui::GetFrameHeightWithSpacing());
    if (show_same_depth_)
      draw_figure("same depth", *results_->same_depth, same_depth_view_, rest);
    else
      draw_figure("stresses", results_->stresses, stress_view_, rest);
  } else {
    draw_figure("stresses", results_->stresses, stress_view_, cell);
  }
  ImGui::EndGroup();
}

void VesselWorkspace::rebuild_scene() {
  scene_dirty_ = false;
  if (!results_ || !results_->converted) return;
  const VesselSurfaces& s = results_->converted->surfaces;
  const SceneBounds bounds = [&] {
    SceneBounds b = bounds_of(s.head);
    const SceneBounds c = bounds_of(s.far_head);
    b.add(c.min);
    b.add(c.max);
    return b;
  }();
  const Eigen::Vector3d origin = bounds.center();
  TriangleMesh mesh = make_surface_mesh(s.head, origin, kHeadRgb, 72, 48);
  append_mesh(mesh, make_surface_mesh(s.cylinder, origin, kSurfaceRgb, 72, 4));
  append_mesh(mesh, make_surface_mesh(s.far_head, origin, kHeadRgb, 72, 48));
  scene_.layer(SceneLayer::surface).upload(mesh);
  LineSet net;
  const float net_rgb[3] = {0.35f, 0.35f, 0.4f};
  add_control_net(net, s.head, origin, net_rgb);
  scene_.layer(SceneLayer::net).upload(net);
  SceneBounds centred;
  centred.add(bounds.min - origin);
  centred.add(bounds.max - origin);
  scene_.set_bounds(centred, false);
}

std::vector<ExportChoice> VesselWorkspace::export_choices() const {
  const bool ready = results_ && results_->converted;
  const std::string stem = document_.path().empty() ? "vessel" : document_.path().stem().string();
  const std::string needs = ready ? "" : "needs a solved and converted head";
  return {
      {{"all", "Export all outputs into the folder", "", stem + "_outputs"},
       "All outputs to a folder…",
       ready,
       "What `polarform vessel` writes: profile and head as IGES, STEP and DXF, the vessel "
       "as a STEP shell, SVG plots, CSV samples, report.html and report.json"},
      {{"iges", "Export IGES", ".igs", stem + "_head.igs"},
       "Head surface as IGES…",
       ready,
       needs,
       true},
      {{"step", "Export STEP", ".stp", stem + ".stp"},
       "Vessel (head, cylinder, far head) as STEP…",
       ready,
       needs},
      {{"dxf", "Export DXF", ".dxf", stem + "_profile.dxf"}, "Head profile as DXF…", ready, needs}};
}

void VesselWorkspace::export_to(const ExportRequest& request, const std::filesystem::path& file) {
  if (!results_ || !results_->converted) return;
  guarded(log(), "Export " + file.filename().string(), [&] {
    VesselOutputOptions options;
    options.design_name = document_.path().empty() ? "vessel" : document_.path().stem().string();
    const VesselJobResult job = run_vessel_job(document_.current());
    if (request.tag == "all") {
      const auto files = write_vessel_outputs(job, file, options);
      log().info("Wrote " + std::to_string(files.size()) + " files into " + file.string());
      return;
    }
    // One file of the job's bundle, byte for byte what `polarform vessel` writes.
    const std::string name = request.tag == "iges"   ? "head.igs"
                             : request.tag == "step" ? "vessel.stp"
                                                     : "profile.dxf";
    write_file_atomically(file, render_vessel_outputs(job, options).at(name));
    log().info("Exported " + file.string() + " (" + name + ")");
  });
}

void VesselWorkspace::bench_step(int frame, int frames) {
  // Scripted edit: the internal pressure raised by up to 50 %, re-solved in the background.
  VesselProject& p = document_.edit();
  if (frame == 0) bench_pressure_ = p.design.pressure;
  p.design.pressure = bench_pressure_ * (1.0 + 0.5 * (frame + 1) / frames);
}

std::string VesselWorkspace::numbers() const {
  if (!results_) return "solved=0\n";
  // The fields of report.json for the stages shown, from the job's own report builder.
  return "solved=1\n" + report_lines(results_->fields);
}

}  // namespace polarform::studio
