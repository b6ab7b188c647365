// The app's colours: the plot palette of export/plot_style (Okabe & Ito, colour-blind safe) as
// ImGui colours, the fixed roles (error, boundary, grid), and the colour maps of export/colormap —
// the sequential map for magnitudes (pressure angle) and the diverging one for signed deviations —
// as ImGui and float colours, so the app and the exported files colour alike.
#pragma once

#include <cstdint>

using ImU32 = unsigned int;

namespace polarform::studio {

// Palette colour k (cycles), opaque or with alpha in [0, 1].
ImU32 palette_color(int k, float alpha = 1.0f);
// "#rrggbb" or "#rgb" to an ImGui colour (grey for malformed text).
ImU32 hex_color(const char* text, float alpha = 1.0f);

namespace color {
inline constexpr ImU32 text = 0xFF222222;
inline constexpr ImU32 muted = 0xFF888888;
inline constexpr ImU32 frame = 0xFF4D4D4D;
inline constexpr ImU32 grid = 0xFFE2E2E2;
inline constexpr ImU32 minor_grid = 0xFFF1F1F1;
inline constexpr ImU32 background = 0xFFFFFFFF;
inline constexpr ImU32 boundary = 0xFF9A9A9A;  // segment boundaries
inline constexpr ImU32 error = 0xFF2020D0;     // discontinuities, violations (ABGR: red)
inline constexpr ImU32 error_band = 0x302020D0;
inline constexpr ImU32 ok = 0xFF3C9E2C;  // met tolerances (green)
}  // namespace color

// Sequential map (viridis-like) of t in [0, 1] (clamped).
ImU32 sequential_color(double t, float alpha = 1.0f);
// Diverging blue–white–red map of t in [-1, 1] (clamped).
ImU32 diverging_color(double t, float alpha = 1.0f);
// The same maps as float RGB for the 3D views.
void sequential_rgb(double t, float* rgb);
void diverging_rgb(double t, float* rgb);

}  // namespace polarform::studio
