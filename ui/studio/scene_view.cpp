#include "ui/studio/scene_view.h"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "ui/studio/gl_api.h"
#include "ui/studio/gl_shader.h"

namespace polarform::studio {
namespace {

constexpr const char* kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 color;
uniform mat4 mvp;
uniform float point_size;
out vec3 v_color;
void main() {
  gl_Position = mvp * vec4(position, 1.0);
  gl_PointSize = point_size;
  v_color = color;
})";

constexpr const char* kFlatFragment = R"(#version 330 core
in vec3 v_color;
out vec4 fragment;
void main() { fragment = vec4(v_color, 1.0); })";

constexpr const char* kLitVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 color;
layout(location = 2) in vec3 normal;
uniform mat4 mvp;
uniform mat4 view;
out vec3 v_color;
out vec3 v_normal;
void main() {
  gl_Position = mvp * vec4(position, 1.0);
  v_normal = mat3(view) * normal;
  v_color = color;
})";

// Two-sided head-light shading with a little specular, so both sides of an open surface read.
constexpr const char* kLitFragment = R"(#version 330 core
in vec3 v_color;
in vec3 v_normal;
out vec4 fragment;
void main() {
  vec3 n = normalize(v_normal);
  float d = abs(n.z);
  float s = pow(d, 24.0);
  fragment = vec4(v_color * (0.28 + 0.72 * d) + vec3(0.18 * s), 1.0);
})";

}  // namespace

SceneView::SceneView() = default;
SceneView::~SceneView() = default;

void SceneView::set_bounds(const SceneBounds& bounds, bool refit) {
  bounds_ = bounds;
  if (refit) refit_ = true;
}

void SceneView::draw(ImVec2 size) {
  size.x = std::max(size.x, 64.0f);
  size.y = std::max(size.y, 64.0f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##scene", size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const bool hovered = ImGui::IsItemHovered();
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive() && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    const bool pan = ImGui::IsMouseDown(ImGuiMouseButton_Right) || io.KeyShift;
    if (pan)
      camera_.pan(io.MouseDelta.x, io.MouseDelta.y, size.y);
    else
      camera_.orbit(io.MouseDelta.x, io.MouseDelta.y);
    moved_ = true;
  }
  if (hovered && io.MouseWheel != 0.0f) {
    camera_.zoom(io.MouseWheel);
    moved_ = true;
  }
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) refit_ = true;
  if (refit_) {
    camera_.fit(bounds_.center().cast<float>(), static_cast<float>(bounds_.radius()));
    refit_ = false;
    changed_ = true;
  }

  Rendered wanted;
  wanted.width = static_cast<int>(size.x * io.DisplayFramebufferScale.x);
  wanted.height = static_cast<int>(size.y * io.DisplayFramebufferScale.y);
  if (moved_)
    moving_budget_.adapt(io.DeltaTime, layers_[static_cast<int>(SceneLayer::cloud)].count());
  wanted.point_budget = moved_ ? moving_budget_.points() : std::numeric_limits<int>::max();
  wanted.visible = visible_;
  wanted.point_size = point_size;
  if (moved_ || changed_ || !(wanted == rendered_)) {
    render(wanted.width, wanted.height, wanted.point_budget);
    rendered_ = wanted;
  }
  moved_ = changed_ = false;
  ImGui::GetWindowDrawList()->AddImage(
      reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(target_.texture())), origin,
      ImVec2(origin.x + size.x, origin.y + size.y), ImVec2(0, 1), ImVec2(1, 0));
  draw_triad(ImVec2(origin.x + 40, origin.y + size.y - 40));
  if (hovered && !ImGui::IsItemActive())
    ImGui::SetTooltip("drag: orbit · right- or shift-drag: pan · wheel: zoom · double-click: fit");
}

void SceneView::render(int width, int height, int point_budget) {
  if (!flat_) {
    flat_ = std::make_unique<GlShader>(kFlatVertex, kFlatFragment);
    lit_ = std::make_unique<GlShader>(kLitVertex, kLitFragment);
  }
  target_.bind(width, height);
  glClearColor(0.97f, 0.97f, 0.98f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_PROGRAM_POINT_SIZE);
  const Eigen::Matrix4f view = camera_.view();
  const Eigen::Matrix4f mvp =
      camera_.projection(static_cast<float>(width) / static_cast<float>(height)) * view;
  for (int i = 0; i < 4; ++i) {
    const GpuLayer& layer = layers_[i];
    if (!visible_[i] || layer.empty()) continue;
    if (layer.kind() == GpuLayer::Kind::triangles) {
      lit_->use();
      lit_->set("mvp", mvp);
      lit_->set("view", view);
      glEnable(GL_POLYGON_OFFSET_FILL);  // lines and points drawn on the surface stay visible
      glPolygonOffset(1.0f, 1.0f);
    } else {
      flat_->use();
      flat_->set("mvp", mvp);
      flat_->set("point_size", point_size);
    }
    layer.draw(point_budget);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_PROGRAM_POINT_SIZE);
  glUseProgram(0);
  RenderTarget::unbind();
}

void SceneView::draw_triad(ImVec2 corner) const {
  const Eigen::Matrix4f view = camera_.view();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const char* names[3] = {"x", "y", "z"};
  const ImU32 colors[3] = {IM_COL32(213, 94, 0, 255), IM_COL32(0, 158, 115, 255),
                           IM_COL32(0, 114, 178, 255)};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3f axis = view.block<3, 3>(0, 0).col(k) * 28.0f;
    const ImVec2 tip(corner.x + axis.x(), corner.y - axis.y());
    dl->AddLine(corner, tip, colors[k], 2.0f);
    dl->AddText(ImVec2(tip.x + 2, tip.y - 8), colors[k], names[k]);
  }
}

}  // namespace polarform::studio
