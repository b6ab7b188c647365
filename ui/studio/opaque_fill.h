// Opaque background rectangles drawn as a scissored clear instead of a textured, blended quad.
// ImGui's OpenGL3 backend shades every pixel of a filled rectangle with a texture lookup and
// blending; a software renderer (Mesa llvmpipe) clears the same pixels for a fraction of that.
// For large opaque backgrounds (plot and profile canvases), pixel-identical to
// ImDrawList::AddRectFilled with an opaque colour and no rounding.
#pragma once

#include <imgui.h>

namespace polarform::studio {

// Fills the pixels whose centres lie in [min, max) (screen coordinates, clipped to the draw
// list's current clip rectangle) with `color`, ignoring its alpha, in draw order.
void add_opaque_rect(ImDrawList* dl, ImVec2 min, ImVec2 max, ImU32 color);

}  // namespace polarform::studio
