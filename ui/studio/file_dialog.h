// An in-app file dialog (GLFW has none): a modal listing one directory — folders first, then the
// files with the wanted extensions — with a path field, a file-name field, parent/home buttons
// and, when saving, a confirmation before replacing a file. Any directory error is shown inline.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace polarform::studio {

class FileDialog {
 public:
  enum class Mode { open, save };

  // Shows the dialog from the next draw(). Extensions are lower-case with the dot (".xml");
  // empty lists every file.
  void show(Mode mode, std::string title, std::vector<std::string> extensions,
            const std::filesystem::path& directory, std::string file_name = {});
  bool visible() const { return visible_; }
  // Draws the dialog; returns the chosen path once, when the user confirms.
  std::optional<std::filesystem::path> draw();

 private:
  void list_directory();
  bool wanted(const std::filesystem::path& file) const;
  std::optional<std::filesystem::path> confirm();

  Mode mode_ = Mode::open;
  std::string title_;
  std::vector<std::string> extensions_;
  std::filesystem::path directory_;
  std::string path_text_, name_;
  std::vector<std::filesystem::path> folders_, files_;
  std::string error_;
  bool visible_ = false, open_popup_ = false, confirm_replace_ = false;
};

}  // namespace polarform::studio
