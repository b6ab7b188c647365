#include "ui/studio/colors.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

#include "export/plot_style.h"

namespace polarform::studio {
namespace {

struct Stop {
  double t;
  float r, g, b;
};

// Viridis at six stops (van der Walt & Smith, matplotlib 2015).
constexpr std::array<Stop, 6> kSequential = {{{0.0, 0.267f, 0.005f, 0.329f},
                                              {0.2, 0.254f, 0.265f, 0.530f},
                                              {0.4, 0.164f, 0.471f, 0.558f},
                                              {0.6, 0.134f, 0.659f, 0.518f},
                                              {0.8, 0.478f, 0.821f, 0.318f},
                                              {1.0, 0.993f, 0.906f, 0.144f}}};
// Blue – white – red (ColorBrewer RdBu, reversed).
constexpr std::array<Stop, 5> kDiverging = {{{-1.0, 0.020f, 0.188f, 0.380f},
                                             {-0.5, 0.263f, 0.576f, 0.765f},
                                             {0.0, 0.969f, 0.969f, 0.969f},
                                             {0.5, 0.839f, 0.376f, 0.302f},
                                             {1.0, 0.404f, 0.000f, 0.122f}}};

template <std::size_t N>
void interpolate(const std::array<Stop, N>& stops, double t, float* rgb) {
  if (!std::isfinite(t)) t = stops.front().t;
  t = std::clamp(t, stops.front().t, stops.back().t);
  std::size_t i = 1;
  while (i + 1 < N && stops[i].t < t) ++i;
  const Stop& a = stops[i - 1];
  const Stop& b = stops[i];
  const float w = static_cast<float>((t - a.t) / (b.t - a.t));
  rgb[0] = a.r + w * (b.r - a.r);
  rgb[1] = a.g + w * (b.g - a.g);
  rgb[2] = a.b + w * (b.b - a.b);
}

}  // namespace

ImU32 hex_color(const char* text, float alpha) {
  if (!text || text[0] != '#') return IM_COL32(128, 128, 128, 255);
  const unsigned long v = std::strtoul(text + 1, nullptr, 16);
  return IM_COL32((v >> 16) & 0xFF, (v >> 8) & 0xFF, v & 0xFF, static_cast<int>(alpha * 255.0f));
}

ImU32 palette_color(int k, float alpha) {
  const auto& p = plot_style::palette;
  const auto index =
      static_cast<std::size_t>(((k % static_cast<int>(p.size())) + p.size()) % p.size());
  return hex_color(std::string(p[index]).c_str(), alpha);
}

void sequential_rgb(double t, float* rgb) { interpolate(kSequential, t, rgb); }
void diverging_rgb(double t, float* rgb) { interpolate(kDiverging, t, rgb); }

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
