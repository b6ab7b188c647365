// The empty state of a workspace with no document: one button per template in
// examples/<folder>, so a first-time user can start without the File menu.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

namespace polarform::studio {

// The templates (*.xml) of a folder, sorted by name.
std::vector<std::filesystem::path> list_templates(const std::filesystem::path& folder);

// Draws `prompt` and the buttons; returns the template clicked.
std::optional<std::filesystem::path> draw_template_picker(const char* prompt,
                                                          const std::filesystem::path& folder);

}  // namespace polarform::studio
