#include "ui/studio/opaque_fill.h"

#include <cmath>
#include <cstdint>

#include "ui/studio/gl_api.h"

namespace polarform::studio {
namespace {

// The draw callback: clears the command's clip rectangle (the rectangle to fill, clipped) to the
// colour carried in its user data, with the scissor the backend would set for it. The backend
// sets its own scissor again for the next command.
void clear_clip_rect(const ImDrawList*, const ImDrawCmd* cmd) {
  const ImDrawData* data = ImGui::GetDrawData();
  const ImVec2 origin = data->DisplayPos, scale = data->FramebufferScale;
  const ImVec2 min((cmd->ClipRect.x - origin.x) * scale.x, (cmd->ClipRect.y - origin.y) * scale.y);
  const ImVec2 max((cmd->ClipRect.z - origin.x) * scale.x, (cmd->ClipRect.w - origin.y) * scale.y);
  if (max.x <= min.x || max.y <= min.y) return;
  const float framebuffer_height = data->DisplaySize.y * scale.y;
  const auto color = static_cast<ImU32>(reinterpret_cast<std::uintptr_t>(cmd->UserCallbackData));
  const ImVec4 c = ImGui::ColorConvertU32ToFloat4(color);
  glScissor(static_cast<int>(min.x), static_cast<int>(framebuffer_height - max.y),
            static_cast<int>(max.x - min.x), static_cast<int>(max.y - min.y));
  glClearColor(c.x, c.y, c.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

// The pixel boundaries of what a filled triangle pair covers: the pixels whose centres lie inside,
// a centre on an edge counting as OpenGL rasterizers (Mesa's, with y flipped) decide a tie.
float pixel_edge_x(float v) { return std::ceil(v - 0.5f); }
float pixel_edge_y(float v) { return std::floor(v + 0.5f); }

}  // namespace

void add_opaque_rect(ImDrawList* dl, ImVec2 min, ImVec2 max, ImU32 color) {
  dl->PushClipRect(ImVec2(pixel_edge_x(min.x), pixel_edge_y(min.y)),
                   ImVec2(pixel_edge_x(max.x), pixel_edge_y(max.y)), true);
  dl->AddCallback(clear_clip_rect, reinterpret_cast<void*>(static_cast<std::uintptr_t>(color)));
  dl->PopClipRect();
}

}  // namespace polarform::studio
