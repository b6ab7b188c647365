#include "ui/studio/log_panel.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>

#include "ui/studio/colors.h"

namespace polarform::studio {
namespace {

constexpr double kToastSeconds = 6.0;

ImU32 severity_color(Severity s) {
  switch (s) {
    case Severity::info:
      return color::text;
    case Severity::warning:
      return IM_COL32(170, 110, 0, 255);
    case Severity::error:
      return color::error;
  }
  return color::text;
}

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::info:
      return "info";
    case Severity::warning:
      return "warning";
    case Severity::error:
      return "error";
  }
  return "";
}

}  // namespace

void LogPanel::draw(MessageLog& log) {
  ImGui::Checkbox("show info", &show_info_);
  ImGui::SameLine();
  if (ImGui::SmallButton("Clear")) log.clear();
  ImGui::Separator();
  ImGui::BeginChild("messages", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
  const std::vector<Message> messages = log.messages();
  for (const Message& m : messages) {
    if (m.severity == Severity::info && !show_info_) continue;
    ImGui::PushStyleColor(ImGuiCol_Text, severity_color(m.severity));
    ImGui::TextWrapped("%s: %s", severity_name(m.severity), m.text.c_str());
    ImGui::PopStyleColor();
  }
  if (messages.size() != seen_) {  // follow new messages
    ImGui::SetScrollHereY(1.0f);
    seen_ = messages.size();
  }
  ImGui::EndChild();
}

void LogPanel::draw_toasts(const MessageLog& log) const {
  const auto now = std::chrono::steady_clock::now();
  std::vector<Message> recent;
  for (const Message& m : log.messages())
    if (m.severity != Severity::info &&
        std::chrono::duration<double>(now - m.time).count() < kToastSeconds)
      recent.push_back(m);
  if (recent.size() > 3) recent.erase(recent.begin(), recent.end() - 3);
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float fh = ImGui::GetFontSize();
  float y = vp->WorkPos.y + vp->WorkSize.y - fh;
  for (int i = static_cast<int>(recent.size()) - 1; i >= 0; --i) {
    const Message& m = recent[i];
    ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x - fh, y), ImGuiCond_Always,
                            ImVec2(1, 1));
    ImGui::SetNextWindowBgAlpha(0.95f);
    ImGui::SetNextWindowSizeConstraints(ImVec2(fh * 10, 0), ImVec2(fh * 32, fh * 10));
    const std::string id = "##toast" + std::to_string(i);
    ImGui::Begin(id.c_str(), nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                     ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
    ImGui::PushTextWrapPos(fh * 30);
    ImGui::PushStyleColor(ImGuiCol_Text, severity_color(m.severity));
    ImGui::TextUnformatted(m.text.c_str());
    ImGui::PopStyleColor();
    ImGui::PopTextWrapPos();
    y -= ImGui::GetWindowHeight() + fh * 0.4f;
    ImGui::End();
  }
}

}  // namespace polarform::studio
