#include "ui/studio/template_picker.h"

#include <imgui.h>

#include <algorithm>

namespace polarform::studio {

std::vector<std::filesystem::path> list_templates(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(folder, ec);
       !ec && it != std::filesystem::directory_iterator(); it.increment(ec))
    if (it->path().extension() == ".xml") files.push_back(it->path());
  std::sort(files.begin(), files.end());
  return files;
}

std::optional<std::filesystem::path> draw_template_picker(const char* prompt,
                                                          const std::filesystem::path& folder) {
  std::optional<std::filesystem::path> chosen;
  ImGui::Spacing();
  ImGui::TextUnformatted(prompt);
  ImGui::Spacing();
  for (const auto& file : list_templates(folder))
    if (ImGui::Button(file.stem().string().c_str(), ImVec2(ImGui::GetFontSize() * 16, 0)))
      chosen = file;
  ImGui::Spacing();
  ImGui::TextDisabled("…or File ▸ Open (Ctrl+O), or drop a project file on the window.");
  return chosen;
}

}  // namespace polarform::studio
