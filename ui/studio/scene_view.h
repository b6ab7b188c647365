// A 3D view inside an ImGui panel: up to four layers (cloud points, shaded surface mesh, lines
// such as control nets, and an extra mesh) rendered into an offscreen target with an orbit
// camera, shown as an image with an axis triad. Mouse: drag orbits, right- or shift-drag pans,
// wheel zooms, double-click fits the view to the content. The image is rendered again only when
// the camera, the layers or the size change; while the camera moves, large clouds are drawn as a
// uniform subset whose size adapts to the frame time (PointBudget), and in full once it stops.
#pragma once

#include <imgui.h>

#include <array>
#include <memory>

#include "ui/studio/gpu_layer.h"
#include "ui/studio/orbit_camera.h"
#include "ui/studio/point_budget.h"
#include "ui/studio/render_target.h"

namespace polarform::studio {

class GlShader;

enum class SceneLayer { cloud, surface, net, extra };

class SceneView {
 public:
  SceneView();
  ~SceneView();

  // A layer to upload to or clear (the view renders again).
  GpuLayer& layer(SceneLayer which) {
    changed_ = true;
    return layers_[static_cast<int>(which)];
  }
  bool& visible(SceneLayer which) { return visible_[static_cast<int>(which)]; }
  // The content's bounding sphere in scene coordinates; the camera frames it on the next draw
  // when `refit` (and always the first time).
  void set_bounds(const SceneBounds& bounds, bool refit);
  void fit() { refit_ = true; }
  // Turns the camera about the vertical axis (scripted views of the benchmark).
  void turn(float radians) {
    camera_.turn(radians);
    moved_ = true;
  }
  float point_size = 2.0f;

  // Renders and shows the view filling `size` at the cursor.
  void draw(ImVec2 size);

 private:
  void render(int width, int height, int point_budget);
  void draw_triad(ImVec2 corner) const;

  std::array<GpuLayer, 4> layers_;
  std::array<bool, 4> visible_ = {true, true, false, true};  // control nets on demand
  RenderTarget target_;
  OrbitCamera camera_;
  SceneBounds bounds_;
  bool refit_ = true;
  bool moved_ = false;   // the camera moved this frame
  bool changed_ = true;  // a layer changed since the last render
  struct Rendered {      // what the image shows
    int width = 0, height = 0, point_budget = 0;
    std::array<bool, 4> visible{};
    float point_size = 0.0f;
    bool operator==(const Rendered&) const = default;
  } rendered_;
  std::unique_ptr<GlShader> flat_, lit_;
  PointBudget moving_budget_;
};

}  // namespace polarform::studio
