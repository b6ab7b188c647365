#include "ui/studio/curvature_table.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <string>

#include "ui/studio/widgets.h"

namespace polarform::studio {

// Where a target is: θ [°], s [mm] or φ [°], chosen in a combo beside its value.
bool CurvatureTable::draw_place(CurvatureEntry& e) {
  static constexpr std::array<std::string_view, 3> kPlaces = {"θ [°]", "s [mm]", "φ [°]"};
  static constexpr std::array<TargetPlace, 3> kValues = {
      TargetPlace::polar_angle, TargetPlace::arc_length, TargetPlace::meridian_angle};
  int place =
      static_cast<int>(std::find(kValues.begin(), kValues.end(), e.place) - kValues.begin());
  bool changed = false;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 4.5f);
  if (combo("##place", place, kPlaces)) {
    e.place = kValues[place];
    e.position = e.place == TargetPlace::meridian_angle ? 90.0 - e.theta_deg : 0.0;
    changed = true;
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (e.place == TargetPlace::polar_angle)
    changed |= drag_number("##theta", e.theta_deg, 0.25, 0.0, 180.0, "%.2f");
  else if (e.place == TargetPlace::arc_length)
    changed |= drag_number("##s", e.position, 1.0, 0.0, 1e7, "%.1f");
  else
    changed |= drag_number("##phi", e.position, 0.25, -90.0, 90.0, "%.2f");
  return changed;
}

bool CurvatureTable::draw(std::vector<CurvatureEntry>& entries) {
  bool changed = false;
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_ScrollY;
  const float height = ImGui::GetTextLineHeightWithSpacing() *
                       std::clamp(static_cast<float>(entries.size()) + 1.5f, 3.0f, 10.0f);
  if (ImGui::BeginTable("curvatures", 5, flags, ImVec2(0, height))) {
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("at");
    ImGui::TableSetupColumn("given as");
    ImGui::TableSetupColumn("value");
    ImGui::TableSetupColumn("weight");
    ImGui::TableHeadersRow();
    for (int i = 0; i < static_cast<int>(entries.size()); ++i) {
      CurvatureEntry& e = entries[i];
      ImGui::PushID(i);
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      if (ImGui::Selectable(
              std::to_string(i + 1).c_str(), selected_ == i,
              ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap))
        selected_ = i;
      ImGui::TableNextColumn();
      changed |= draw_place(e);
      ImGui::TableNextColumn();
      ImGui::SetNextItemWidth(-FLT_MIN);
      int kind = e.is_radius ? 1 : 0;
      static constexpr std::string_view kKinds[] = {"κ [1/mm]", "radius [mm]"};
      if (combo("##kind", kind, kKinds)) {
        // Keep the same curvature, expressed the other way.
        if (e.value != 0.0) e.value = 1.0 / e.value;
        e.is_radius = kind == 1;
        changed = true;
      }
      ImGui::TableNextColumn();
      ImGui::SetNextItemWidth(-FLT_MIN);
      changed |= e.is_radius ? drag_number("##value", e.value, 1.0, -1e7, 1e7, "%.4g")
                             : drag_number("##value", e.value, 1e-5, -10.0, 10.0, "%.5g");
      ImGui::TableNextColumn();
      ImGui::SetNextItemWidth(-FLT_MIN);
      changed |= drag_number("##weight", e.weight, 0.05, 1e-6, 1e6, "%.3g");
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  if (ImGui::Button("Add target")) {
    CurvatureEntry e;
    if (!entries.empty()) {
      e = entries.back();
      e.theta_deg = std::min(180.0, e.theta_deg + 10.0);
    } else {
      e.value = 0.002;
    }
    entries.push_back(e);
    selected_ = static_cast<int>(entries.size()) - 1;
    changed = true;
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(selected_ < 0 || selected_ >= static_cast<int>(entries.size()));
  if (ImGui::Button("Delete")) {
    entries.erase(entries.begin() + selected_);
    selected_ = -1;
    changed = true;
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Sort by θ")) {
    std::stable_sort(
        entries.begin(), entries.end(),
        [](const CurvatureEntry& a, const CurvatureEntry& b) { return a.theta_deg < b.theta_deg; });
    changed = true;
  }
  help_marker(
      "Prescribed curvatures of the head meridian, each at a polar angle θ (0° junction A, 90° "
      "apex, 180° junction B), an arc length s from junction A, or a meridian angle φ of the "
      "normal against the axis (90° at junction A, 0° at the apex, -90° at junction B). With no "
      "targets, the preset's curvature is sampled instead.");
  return changed;
}

}  // namespace polarform::studio
