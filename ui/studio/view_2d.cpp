#include "ui/studio/view_2d.h"

#include <algorithm>
#include <cmath>

namespace polarform::studio {

void View2d::set_canvas(ImVec2 min, ImVec2 max, const Box2& content) {
  min_ = min;
  max_ = max;
  if (!user_moved_) fit_to(content);
}

void View2d::fit_to(const Box2& box) {
  const double w = std::max(box.max_x - box.min_x, 1e-9), h = std::max(box.max_y - box.min_y, 1e-9);
  center_x_ = 0.5 * (box.min_x + box.max_x);
  center_y_ = 0.5 * (box.min_y + box.max_y);
  scale_ = 0.92 * std::min((max_.x - min_.x) / w, (max_.y - min_.y) / h);
  if (!(scale_ > 0) || !std::isfinite(scale_)) scale_ = 1.0;
}

void View2d::handle_input(bool hovered, bool active) {
  const ImGuiIO& io = ImGui::GetIO();
  if (hovered && io.MouseWheel != 0.0f) {
    double mx, my;
    to_model(io.MousePos, &mx, &my);
    const double factor = std::pow(1.18, io.MouseWheel);
    const double next = std::clamp(scale_ * factor, 1e-6, 1e9);
    // Keep the model point under the cursor in place.
    center_x_ = mx - (mx - center_x_) * scale_ / next;
    center_y_ = my - (my - center_y_) * scale_ / next;
    scale_ = next;
    user_moved_ = true;
  }
  if (active && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 1.0f)) {
    center_x_ -= io.MouseDelta.x / scale_;
    center_y_ += io.MouseDelta.y / scale_;
    user_moved_ = true;
  }
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) user_moved_ = false;
}

ImVec2 View2d::to_screen(double x, double y) const {
  return ImVec2(static_cast<float>(0.5 * (min_.x + max_.x) + (x - center_x_) * scale_),
                static_cast<float>(0.5 * (min_.y + max_.y) - (y - center_y_) * scale_));
}

void View2d::to_model(ImVec2 p, double* x, double* y) const {
  *x = center_x_ + (p.x - 0.5 * (min_.x + max_.x)) / scale_;
  *y = center_y_ - (p.y - 0.5 * (min_.y + max_.y)) / scale_;
}

}  // namespace polarform::studio
