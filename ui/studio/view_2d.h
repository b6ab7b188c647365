// Pan and zoom of a 2-D drawing in model units (mm) with equal aspect: the transform between
// model and screen, fitting a bounding box, and the mouse handling of a canvas (wheel zooms about
// the cursor, drag pans, double-click fits again).
#pragma once

#include <imgui.h>

namespace polarform::studio {

struct Box2 {
  double min_x = 0, min_y = 0, max_x = 1, max_y = 1;
};

class View2d {
 public:
  // The canvas rectangle for this frame; keeps the view fitted until the user moves it.
  void set_canvas(ImVec2 min, ImVec2 max, const Box2& content);
  // Mouse input over the canvas item (call after the item that covers it).
  void handle_input(bool hovered, bool active);
  void fit() { user_moved_ = false; }

  ImVec2 to_screen(double x, double y) const;
  void to_model(ImVec2 p, double* x, double* y) const;
  double pixels_per_unit() const { return scale_; }

 private:
  void fit_to(const Box2& box);

  ImVec2 min_{0, 0}, max_{1, 1};
  double center_x_ = 0, center_y_ = 0;  // model point at the canvas centre
  double scale_ = 1;                    // pixels per mm
  bool user_moved_ = false;
};

}  // namespace polarform::studio
