#include "ui/studio/orbit_camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace polarform::studio {

void OrbitCamera::fit(const Eigen::Vector3f& center, float radius) {
  target_ = center;
  radius_ = std::max(radius, 1e-6f);
  distance_ = radius_ / std::sin(0.5f * fov_) * 1.05f;
  yaw_ = -0.9f;
  pitch_ = 0.45f;
}

void OrbitCamera::orbit(float dx, float dy) {
  yaw_ -= dx * 0.008f;
  pitch_ = std::clamp(pitch_ + dy * 0.008f, -1.55f, 1.55f);
}

void OrbitCamera::pan(float dx, float dy, float viewport_height) {
  const float units_per_pixel =
      2.0f * distance_ * std::tan(0.5f * fov_) / std::max(viewport_height, 1.0f);
  const Eigen::Matrix4f v = view();
  const Eigen::Vector3f right = v.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3f up = v.block<1, 3>(1, 0).transpose();
  target_ += (-dx * right + dy * up) * units_per_pixel;
}

void OrbitCamera::zoom(float wheel_steps) {
  distance_ = std::clamp(distance_ * std::pow(0.85f, wheel_steps), radius_ * 1e-3f, radius_ * 1e3f);
}

Eigen::Vector3f OrbitCamera::eye() const {
  const Eigen::Vector3f dir(std::cos(pitch_) * std::cos(yaw_), std::cos(pitch_) * std::sin(yaw_),
                            std::sin(pitch_));
  return target_ + distance_ * dir;
}

Eigen::Matrix4f OrbitCamera::view() const {
  const Eigen::Vector3f e = eye();
  const Eigen::Vector3f f = (target_ - e).normalized();
  const Eigen::Vector3f s = f.cross(Eigen::Vector3f::UnitZ()).normalized();
  const Eigen::Vector3f u = s.cross(f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(e);
  m(1, 3) = -u.dot(e);
  m(2, 3) = f.dot(e);
  return m;
}

Eigen::Matrix4f OrbitCamera::projection(float aspect) const {
  const float near_plane = std::max(distance_ - 2.0f * radius_, distance_ * 1e-3f);
  const float far_plane = distance_ + 2.0f * radius_;
  const float t = 1.0f / std::tan(0.5f * fov_);
  Eigen::Matrix4f p = Eigen::Matrix4f::Zero();
  p(0, 0) = t / std::max(aspect, 1e-3f);
  p(1, 1) = t;
  p(2, 2) = -(far_plane + near_plane) / (far_plane - near_plane);
  p(2, 3) = -2.0f * far_plane * near_plane / (far_plane - near_plane);
  p(3, 2) = -1.0f;
  return p;
}

}  // namespace polarform::studio
