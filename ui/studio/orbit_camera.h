// The 3D views' camera: orbits about a target point with the model's z axis up (yaw about z,
// pitch towards it), pans in the view plane, zooms by distance, and fits a bounding sphere.
// Produces the view and perspective projection matrices for OpenGL (column-major, float).
#pragma once

#include <Eigen/Core>

namespace polarform::studio {

class OrbitCamera {
 public:
  // Frames a sphere (scene coordinates) and resets the angles to a three-quarter view.
  void fit(const Eigen::Vector3f& center, float radius);
  void orbit(float dx_pixels, float dy_pixels);
  void turn(float radians) { yaw_ += radians; }
  void pan(float dx_pixels, float dy_pixels, float viewport_height);
  void zoom(float wheel_steps);

  Eigen::Matrix4f view() const;
  Eigen::Matrix4f projection(float aspect) const;

 private:
  Eigen::Vector3f eye() const;

  Eigen::Vector3f target_ = Eigen::Vector3f::Zero();
  float distance_ = 10.0f;
  float radius_ = 1.0f;
  float yaw_ = -0.9f, pitch_ = 0.45f;  // radians
  float fov_ = 0.6f;                   // vertical field of view, radians
};

}  // namespace polarform::studio
