#include "ui/studio/colors.h"

#include <imgui.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

#include "export/colormap.h"
#include "export/plot_style.h"

namespace polarform::studio {

ImU32 hex_color(const char* text, float alpha) {
  const std::size_t n = text ? std::strlen(text) : 0;
  if (n != 4 && n != 7) return IM_COL32(128, 128, 128, 255);
  if (text[0] != '#') return IM_COL32(128, 128, 128, 255);
  unsigned long v = std::strtoul(text + 1, nullptr, 16);
  if (n == 4)  // #rgb: each digit doubled
    v = ((v >> 8) & 0xF) * 0x110000 + ((v >> 4) & 0xF) * 0x1100 + (v & 0xF) * 0x11;
  return IM_COL32((v >> 16) & 0xFF, (v >> 8) & 0xFF, v & 0xFF, static_cast<int>(alpha * 255.0f));
}

ImU32 palette_color(int k, float alpha) {
  const auto& p = plot_style::palette;
  const auto index =
      static_cast<std::size_t>(((k % static_cast<int>(p.size())) + p.size()) % p.size());
  return hex_color(std::string(p[index]).c_str(), alpha);
}

void sequential_rgb(double t, float* rgb) {
  if (!std::isfinite(t)) t = 0.0;
  const Eigen::Vector3d c = polarform::sequential_color(t, 0.0, 1.0);
  for (int k = 0; k < 3; ++k) rgb[k] = static_cast<float>(c[k]);
}

void diverging_rgb(double t, float* rgb) {
  if (!std::isfinite(t)) t = 0.0;
  const Eigen::Vector3d c = polarform::diverging_color(t, 1.0);
  for (int k = 0; k < 3; ++k) rgb[k] = static_cast<float>(c[k]);
}

ImU32 sequential_color(double t, float alpha) {
  float rgb[3];
  sequential_rgb(t, rgb);
  return ImGui::ColorConvertFloat4ToU32(ImVec4(rgb[0], rgb[1], rgb[2], alpha));
}

ImU32 diverging_color(double t, float alpha) {
  float rgb[3];
  diverging_rgb(t, rgb);
  return ImGui::ColorConvertFloat4ToU32(ImVec4(rgb[0], rgb[1], rgb[2], alpha));
}

}  // namespace polarform::studio
