// An offscreen framebuffer (RGBA colour texture + depth buffer) that a 3D view renders into and
// Dear ImGui then shows as an image; resized to the view's pixel size on demand.
#pragma once

namespace polarform::studio {

class RenderTarget {
 public:
  RenderTarget() = default;
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // Binds the framebuffer (created or resized to width x height) and sets the viewport.
  void bind(int width, int height);
  // Restores the default framebuffer.
  static void unbind();
  unsigned texture() const { return color_; }

 private:
  void release();

  unsigned framebuffer_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace polarform::studio
