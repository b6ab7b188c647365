#include "ui/studio/splitter.h"

#include <imgui.h>

#include <algorithm>

namespace polarform::studio {
namespace {

constexpr float kThickness = 6.0f;

void drag_bar(const char* id, float& fraction, float length, bool vertical) {
  const ImVec2 size = vertical ? ImVec2(kThickness, ImGui::GetContentRegionAvail().y)
                               : ImVec2(ImGui::GetContentRegionAvail().x, kThickness);
  const ImVec2 pos = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size);
  const bool hot = ImGui::IsItemHovered() || ImGui::IsItemActive();
  if (hot) ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
  if (ImGui::IsItemActive() && length > 0) {
    const float delta = vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y;
    fraction += delta / length;
  }
  fraction = std::clamp(fraction, 0.02f, 0.98f);
  const ImU32 c = ImGui::GetColorU32(hot ? ImGuiCol_SeparatorActive : ImGuiCol_Separator);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  if (vertical)
    dl->AddLine(ImVec2(pos.x + size.x * 0.5f, pos.y), ImVec2(pos.x + size.x * 0.5f, pos.y + size.y),
                c, hot ? 3.0f : 1.0f);
  else
    dl->AddLine(ImVec2(pos.x, pos.y + size.y * 0.5f), ImVec2(pos.x + size.x, pos.y + size.y * 0.5f),
                c, hot ? 3.0f : 1.0f);
}

}  // namespace

float split_size(float fraction, float length, float min_size) {
  const float usable = length - kThickness;
  if (usable <= 2 * min_size) return std::max(usable * 0.5f, 1.0f);
  return std::clamp(fraction * usable, min_size, usable - min_size);
}

void vertical_splitter(const char* id, float& fraction, float length) {
  drag_bar(id, fraction, length, true);
}

void horizontal_splitter(const char* id, float& fraction, float length) {
  drag_bar(id, fraction, length, false);
}

}  // namespace polarform::studio
