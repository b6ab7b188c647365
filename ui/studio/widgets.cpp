#include "ui/studio/widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace polarform::studio {

bool input_number(const char* label, double& value, double step, const char* format) {
  double v = value;
  if (!ImGui::InputDouble(label, &v, step, step * 10, format)) return false;
  if (!std::isfinite(v)) return false;
  value = v;
  return true;
}

bool drag_number(const char* label, double& value, double speed, double min, double max,
                 const char* format) {
  double v = value;
  if (!ImGui::DragScalar(label, ImGuiDataType_Double, &v, static_cast<float>(speed), &min, &max,
                         format, ImGuiSliderFlags_AlwaysClamp))
    return false;
  value = v;
  return true;
}

bool drag_angle(const char* label, double& radians, double min_deg, double max_deg) {
  double deg = radians * kDegreesPerRadian;
  if (!ImGui::DragScalar(label, ImGuiDataType_Double, &deg, 0.25f, &min_deg, &max_deg, "%.2f°",
                         ImGuiSliderFlags_AlwaysClamp))
    return false;
  radians = deg * kRadiansPerDegree;
  return true;
}

bool input_int(const char* label, int& value, int min, int max) {
  int v = value;
  if (!ImGui::InputInt(label, &v)) return false;
  v = std::clamp(v, min, max);
  if (v == value) return false;
  value = v;
  return true;
}

bool log_slider(const char* label, double& value, double min, double max, const char* format) {
  double v = std::clamp(value, min, max);
  if (!ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &min, &max, format,
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    return false;
  value = v;
  return true;
}

bool combo(const char* label, int& index, std::span<const std::string_view> names) {
  bool changed = false;
  const std::string preview(index >= 0 && index < static_cast<int>(names.size()) ? names[index]
                                                                                 : "");
  if (ImGui::BeginCombo(label, preview.c_str())) {
    for (int i = 0; i < static_cast<int>(names.size()); ++i) {
      const std::string name(names[i]);
      if (ImGui::Selectable(name.c_str(), i == index) && i != index) {
        index = i;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

void help_marker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", title);
  ImGui::Separator();
}

}  // namespace polarform::studio
