#include "ui/studio/dynamics_panel.h"

#include "jobs/cam/cam_key_figures.h"
#include "jobs/cam/cam_plots.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

// A start that holds contact at moderate speeds: 0.5 kg on 10 N/mm with 50 N preload, or an arm of
// 0.01 kg·m² on 50 N·m/rad with 10 N·m preload (a project needs a mass or inertia > 0).
FollowerLoad default_load(FollowerKind follower) {
  FollowerLoad load;
  if (is_oscillating(follower)) {
    load.arm = true, load.inertia = 0.01, load.torsion_rate = 50, load.preload_torque = 10;
  } else {
    load.mass = 0.5, load.spring_rate = 10, load.preload = 50;
  }
  return load;
}

}  // namespace

bool draw_dynamics_settings(std::optional<FollowerLoad>& load, FollowerKind follower) {
  bool enabled = load.has_value();
  bool changed = false;
  if (ImGui::Checkbox("follower dynamics", &enabled)) {
    load = enabled ? std::optional<FollowerLoad>(default_load(follower)) : std::nullopt;
    changed = true;
  }
  if (!load) return changed;
  if (load->arm != is_oscillating(follower)) {  // the follower changed kind: so does its load
    const FollowerLoad contact = *load;
    load = default_load(follower);
    load->contact_width = contact.contact_width;
    load->youngs_modulus = contact.youngs_modulus;
    load->poisson_ratio = contact.poisson_ratio;
    changed = true;
  }
  const float width = ImGui::GetFontSize() * 9;
  ImGui::PushItemWidth(width);
  if (load->arm) {
    changed |= drag_number("inertia [kg·m²]", load->inertia, 1e-4, 0.0, 1e4, "%.5g");
    changed |= drag_number("torsion rate [N·m/rad]", load->torsion_rate, 0.5, 0.0, 1e7, "%.4g");
    changed |= drag_number("preload torque [N·m]", load->preload_torque, 0.1, 0.0, 1e7, "%.4g");
    changed |= drag_number("damping [N·m·s/rad]", load->torsion_damping, 0.01, 0.0, 1e6, "%.4g");
  } else {
    changed |= drag_number("mass [kg]", load->mass, 0.01, 0.0, 1e5, "%.4g");
    changed |= drag_number("spring rate [N/mm]", load->spring_rate, 0.1, 0.0, 1e7, "%.4g");
    changed |= drag_number("preload [N]", load->preload, 1.0, 0.0, 1e8, "%.4g");
    changed |= drag_number("damping [N·s/mm]", load->damping, 0.01, 0.0, 1e6, "%.4g");
  }
  changed |= drag_number("contact width [mm]", load->contact_width, 0.1, 0.0, 1e4, "%.4g");
  changed |= drag_number("Young's modulus [MPa]", load->youngs_modulus, 100.0, 1.0, 1e7, "%.6g");
  changed |= drag_number("Poisson ratio", load->poisson_ratio, 0.005, 0.0, 0.499, "%.3f");
  ImGui::PopItemWidth();
  return changed;
}

void draw_dynamics_summary(const CamDesignStage& design, const CamAnalysisStage& analysis) {
  if (!analysis.dynamics || !design.project.load) {
    ImGui::TextDisabled(
        std::holds_alternative<PlateCam>(design.cam)
            ? "Tick \"follower dynamics\" for the contact force, the jump speed and the stress."
            : "Follower dynamics are computed for plate cams.");
    return;
  }
  if (!ImGui::BeginTable("dynamics", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp))
    return;
  for (const KeyFigure& f : cam_dynamics_figures(*analysis.dynamics, *design.project.load)) {
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(f.name.c_str());
    ImGui::TableNextColumn();
    ImGui::TextWrapped("%s", f.value.c_str());
  }
  ImGui::EndTable();
}

void DynamicsPlots::draw(const CamDesignStage& design, const CamAnalysisStage& analysis,
                         std::uint64_t revision, ImVec2 size) {
  if (!analysis.dynamics) {
    figures_.clear();
    ImGui::TextDisabled("No dynamics: tick \"follower dynamics\" under Dynamics.");
    return;
  }
  if (figures_.empty() || revision != revision_) {
    figures_ = {contact_force_figure(design, analysis), camshaft_torque_figure(design, analysis)};
    if (analysis.dynamics->largest_stress.contact_stress > 0)
      figures_.push_back(contact_stress_figure(design, analysis));
    views_.resize(figures_.size());
    revision_ = revision;
  }
  const float each = size.y / static_cast<float>(figures_.size());
  for (std::size_t k = 0; k < figures_.size(); ++k) {
    ImGui::PushID(static_cast<int>(k));
    draw_figure("dynamics", figures_[k], views_[k], ImVec2(size.x, each));
    ImGui::PopID();
  }
}

}  // namespace polarform::studio
