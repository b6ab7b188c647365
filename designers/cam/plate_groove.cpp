#include "designers/cam/plate_groove.h"

#include "designers/cam/contour_polar_function.h"
#include "src/error.h"

namespace polarform {

RollerImage groove_outer_flank(const PlateCam& cam) {
  if (!has_roller(cam.follower().kind))
    throw InputError(
        "groove-depth: a grooved plate cam needs a roller follower (roller or "
        "oscillating-roller); a knife edge or a flat face cannot ride in a groove");
  return {1.0, 0.0, Eigen::Vector2d::Zero(), -cam.follower().roller_radius};
}

PolarFunction groove_outer_flank_function(const PlateCam& cam) {
  return roller_image_polar_function(
      cam, groove_outer_flank(cam), "groove outer flank",
      "the pitch curve is concave there with a radius of curvature below the roller radius "
      "(1 + Rr·κ <= 0): reduce the roller radius, increase the base radius or lengthen the "
      "segment");
}

}  // namespace polarform
