#include "ui/studio/font_setup.h"

#include <imgui.h>

#include <filesystem>

namespace polarform::studio {
namespace {

constexpr float kBaseSize = 15.0f;
constexpr const char* kSansFiles[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                      "/usr/share/fonts/dejavu/DejaVuSans.ttf"};

// Latin-1, Greek, general punctuation (–, …), super/subscripts, arrows, math operators,
// geometric shapes (▸).
constexpr ImWchar kRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x2027, 0x2070, 0x209F,
                               0x2190, 0x21FF, 0x2200, 0x22FF, 0x25A0, 0x25FF, 0};

ImFont* load_first(ImGuiIO& io, const char* const* files, std::size_t count, float size) {
  for (std::size_t i = 0; i < count; ++i) {
    std::error_code ec;
    if (std::filesystem::exists(files[i], ec)) {
      ImFontConfig config;
      config.OversampleH = 2;
      return io.Fonts->AddFontFromFileTTF(files[i], size, &config, kRanges);
    }
  }
  return nullptr;
}

}  // namespace

void build_fonts(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  const float size = std::max(8.0f, kBaseSize * scale);
  ImFont* font = load_first(io, kSansFiles, std::size(kSansFiles), size);
  if (!font) {
    ImFontConfig config;
    config.SizePixels = std::max(13.0f, 13.0f * scale);
    font = io.Fonts->AddFontDefault(&config);
  }
  io.FontDefault = font;

  ImGuiStyle style;
  ImGui::StyleColorsLight(&style);
  style.WindowRounding = 3.0f;
  style.FrameRounding = 2.0f;
  style.GrabRounding = 2.0f;
  style.ScrollbarSize = 12.0f;
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
}

}  // namespace polarform::studio
