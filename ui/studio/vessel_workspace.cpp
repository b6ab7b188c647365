#include "ui/studio/vessel_workspace.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "export/iges_writer.h"
#include "export/step_writer.h"
#include "export/x3d_writer.h"
#include "jobs/vessel/vessel_outputs.h"
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
      for (const auto& w : results_->solution.warnings) log().warning("Vessel: " + w);
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
    task_.start([project = current](TaskControl&) { return compute_vessel_results(project); });
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
  section("Synthesis result");
  if (task_.busy()) ImGui::TextColored(ImVec4(0.1f, 0.4f, 0.8f, 1), "solving…");
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, color::error);
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
    if (results_) ImGui::TextDisabled("Showing the last design that could be solved.");
  }
  if (!results_) return;
  const SynthesisResult& s = results_->solution.synthesis;
  double worst = 0.0;
  for (const TargetResidual& t : s.targets) worst = std::max(worst, std::abs(t.residual()));
  ImGui::Text("%d targets, %d unknowns, %d free parameters", static_cast<int>(s.targets.size()),
              s.unknowns, s.free_parameters);
  ImGui::Text("NLopt: %d evaluations, %s (%.2f s)", s.iterations, s.termination.c_str(),
              solve_seconds_);
  ImGui::Text("max |κ − κₖ| = %.3g 1/mm, objective %.3g", worst, s.objective);
  ImGui::Text("stationarity %.2g, max condition violation %.2g", s.stationarity, s.max_violation);
  ImGui::Text("depth %.4g mm, smallest R %.4g mm at %.1f°", results_->solution.depth, s.min_radius,
              s.min_radius_angle * kDegreesPerRadian);
  ImGui::Text("junction: κ = %.4g 1/mm, slope %.3g°", results_->solution.junction_curvature,
              results_->solution.junction_slope * kDegreesPerRadian);
  if (results_->conversion)
    ImGui::Text("NURBS: %s", results_->conversion->text().c_str());
  else if (!results_->conversion_error.empty())
    ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "%s", results_->conversion_error.c_str());
  const float h = std::max(ImGui::GetFontSize() * 10, ImGui::GetContentRegionAvail().y);
  plots_.draw_residuals(*results_, ImVec2(ImGui::GetContentRegionAvail().x, h));
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
  plots_.draw_meridian(*results_, cell);
  ImGui::SameLine();
  ImGui::BeginGroup();
  if (results_->surfaces) {
    ImGui::Checkbox("control net", &scene_.visible(SceneLayer::net));
    scene_.draw(ImVec2(cell.x, cell.y - ImGui::GetFrameHeightWithSpacing()));
  } else {
    ImGui::TextDisabled("No surfaces: %s", results_->conversion_error.c_str());
  }
  ImGui::EndGroup();
  plots_.draw_curvature(*results_, cell);
  ImGui::SameLine();
  plots_.draw_stresses(*results_, cell);
}

void VesselWorkspace::rebuild_scene() {
  scene_dirty_ = false;
  if (!results_ || !results_->surfaces) return;
  const VesselSurfaces& s = *results_->surfaces;
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
  const bool ready = results_ && results_->surfaces;
  const std::string stem = document_.path().empty() ? "vessel" : document_.path().stem().string();
  const std::string needs = ready ? "" : "needs a solved and converted head";
  return {{{"all", "Export all outputs into the folder", "", stem + "_outputs"},
           "All outputs to a folder…",
           ready,
           "What `polarform vessel` writes: profile and head as IGES, STEP and DXF, the vessel "
           "as a STEP shell, SVG plots, CSV samples, report.html and report.json"},
          {{"iges", "Export IGES", ".igs", stem + ".igs"}, "Surfaces as IGES…", ready, needs, true},
          {{"step", "Export STEP", ".stp", stem + ".stp"}, "Surfaces as STEP…", ready, needs},
          {{"x3d", "Export X3D", ".x3d", stem + ".x3d"}, "Surfaces as X3D…", ready, needs}};
}

void VesselWorkspace::export_to(const ExportRequest& request, const std::filesystem::path& file) {
  if (!results_ || !results_->surfaces) return;
  const VesselSurfaces& s = *results_->surfaces;
  guarded(log(), "Export " + file.filename().string(), [&] {
    if (request.tag == "all") {
      VesselOutputOptions options;
      options.design_name =
          document_.path().empty() ? "vessel" : document_.path().stem().string();
      const auto files = write_vessel_outputs(run_vessel_job(document_.current()), file, options);
      log().info("Wrote " + std::to_string(files.size()) + " files into " + file.string());
      return;
    }
    if (request.tag == "iges") {
      IgesWriter w;
      w.add(s.head, "head");
      w.add(s.cylinder, "cylinder");
      w.add(s.far_head, "far head");
      w.save(file);
    } else if (request.tag == "step") {
      StepWriter w("vessel");
      w.add(s.head, "head");
      w.add(s.cylinder, "cylinder");
      w.add(s.far_head, "far head");
      w.save(file);
    } else if (request.tag == "x3d") {
      X3dWriter w;
      w.add(s.head, "head");
      w.add(s.cylinder, "cylinder");
      w.add(s.far_head, "far_head");
      w.save(file, document_.name());
    }
    log().info("Exported " + file.string());
  });
}

void VesselWorkspace::bench_step(int frame, int frames) {
  // Scripted edit: the internal pressure raised by up to 50 %, re-solved in the background.
  VesselProject& p = document_.edit();
  if (frame == 0) bench_pressure_ = p.design.pressure;
  p.design.pressure = bench_pressure_ * (1.0 + 0.5 * (frame + 1) / frames);
}

std::string VesselWorkspace::numbers() const {
  std::ostringstream out;
  if (!results_) {
    out << "solved=0\n";
    return out.str();
  }
  const VesselSolution& s = results_->solution;
  double worst = 0.0, hoop = 0.0;
  for (const TargetResidual& t : s.synthesis.targets)
    worst = std::max(worst, std::abs(t.residual()));
  for (const StressSample& x : s.stresses.samples) hoop = std::max(hoop, x.hoop_stress);
  out << "solved=1\npressure_mpa=" << results_->project.design.pressure << "\ndepth_mm=" << s.depth
      << "\nmax_abs_residual_per_mm=" << worst << "\niterations=" << s.synthesis.iterations
      << "\nmax_hoop_stress_mpa=" << hoop << "\n";
  if (results_->conversion) out << results_->conversion->numbers();
  return out.str();
}

}  // namespace polarform::studio
