#include "ui/studio/file_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace polarform::studio {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

void FileDialog::show(Mode mode, std::string title, std::vector<std::string> extensions,
                      const std::filesystem::path& directory, std::string file_name) {
  mode_ = mode;
  title_ = std::move(title);
  extensions_ = std::move(extensions);
  std::error_code ec;
  directory_ =
      std::filesystem::is_directory(directory, ec) ? directory : std::filesystem::current_path(ec);
  name_ = std::move(file_name);
  visible_ = open_popup_ = true;
  confirm_replace_ = false;
  list_directory();
}

bool FileDialog::wanted(const std::filesystem::path& file) const {
  if (extensions_.empty()) return true;
  const std::string ext = lower(file.extension().string());
  return std::find(extensions_.begin(), extensions_.end(), ext) != extensions_.end();
}

void FileDialog::list_directory() {
  folders_.clear();
  files_.clear();
  error_.clear();
  path_text_ = directory_.string();
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(directory_, ec);
       !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
    const auto& p = it->path();
    if (p.filename().string().starts_with(".")) continue;
    std::error_code type_ec;
    if (it->is_directory(type_ec))
      folders_.push_back(p);
    else if (wanted(p))
      files_.push_back(p);
  }
  if (ec) error_ = "cannot list " + directory_.string() + ": " + ec.message();
  std::sort(folders_.begin(), folders_.end());
  std::sort(files_.begin(), files_.end());
}

std::optional<std::filesystem::path> FileDialog::confirm() {
  if (name_.empty()) return std::nullopt;
  std::filesystem::path chosen = std::filesystem::path(name_).is_absolute()
                                     ? std::filesystem::path(name_)
                                     : directory_ / name_;
  std::error_code ec;
  if (mode_ == Mode::save && extensions_.size() == 1 && chosen.extension().empty())
    chosen += extensions_.front();
  if (mode_ == Mode::open && !std::filesystem::is_regular_file(chosen, ec)) {
    error_ = "no such file: " + chosen.string();
    return std::nullopt;
  }
  if (mode_ == Mode::save && std::filesystem::exists(chosen, ec) && !confirm_replace_) {
    confirm_replace_ = true;
    error_ = chosen.filename().string() + " exists. Press Save again to replace it.";
    return std::nullopt;
  }
  visible_ = false;
  ImGui::CloseCurrentPopup();
  return chosen;
}

std::optional<std::filesystem::path> FileDialog::draw() {
  if (!visible_) return std::nullopt;
  if (open_popup_) {
    ImGui::OpenPopup(title_.c_str());
    open_popup_ = false;
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowSize(ImVec2(vp->WorkSize.x * 0.5f, vp->WorkSize.y * 0.6f),
                           ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(
      ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
      ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  bool open = true;
  std::optional<std::filesystem::path> result;
  if (!ImGui::BeginPopupModal(title_.c_str(), &open)) {
    visible_ = open && visible_;
    return std::nullopt;
  }
  if (ImGui::Button("Up")) {
    directory_ = directory_.parent_path();
    list_directory();
  }
  ImGui::SameLine();
  if (ImGui::Button("Home")) {
    if (const char* home = std::getenv("HOME")) directory_ = home;
    list_directory();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (ImGui::InputText("##path", &path_text_, ImGuiInputTextFlags_EnterReturnsTrue)) {
    std::error_code ec;
    if (std::filesystem::is_directory(path_text_, ec)) {
      directory_ = path_text_;
      list_directory();
    } else {
      error_ = "not a directory: " + path_text_;
    }
  }
  const float footer = ImGui::GetFrameHeightWithSpacing() * 2.2f;
  ImGui::BeginChild("entries", ImVec2(0, -footer), true);
  std::optional<std::filesystem::path> enter;
  for (const auto& f : folders_)
    if (ImGui::Selectable((f.filename().string() + "/").c_str(), false,
                          ImGuiSelectableFlags_AllowDoubleClick) &&
        ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
      enter = f;
  for (const auto& f : files_) {
    const std::string name = f.filename().string();
    if (ImGui::Selectable(name.c_str(), name == name_, ImGuiSelectableFlags_AllowDoubleClick)) {
      name_ = name;
      confirm_replace_ = false;
      if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) result = confirm();
    }
  }
  ImGui::EndChild();
  if (enter) {
    directory_ = *enter;
    list_directory();
  }
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 12);
  if (ImGui::InputTextWithHint("##name", "file name", &name_, ImGuiInputTextFlags_EnterReturnsTrue))
    result = confirm();
  if (ImGui::IsItemEdited()) confirm_replace_ = false;
  ImGui::SameLine();
  if (ImGui::Button(mode_ == Mode::open ? "Open" : "Save")) result = confirm();
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) {
    visible_ = false;
    ImGui::CloseCurrentPopup();
  }
  if (!error_.empty()) ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "%s", error_.c_str());
  ImGui::EndPopup();
  if (!open) visible_ = false;
  return result;
}

}  // namespace polarform::studio
