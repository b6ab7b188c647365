// DPI-aware fonts: DejaVu Sans rasterised at the window's content scale, with the Greek letters
// and math signs the app prints (θ, κ, ρ, °, ², −, ≤, ×); Dear ImGui's built-in font scaled up
// when DejaVu is not installed. The style scales with them.
#pragma once

namespace polarform::studio {

// Rebuilds the font atlas of the current ImGui context for `scale` (1 = 96 dpi) and rescales the
// style. The renderer's font texture must be recreated afterwards.
void build_fonts(float scale);

}  // namespace polarform::studio
