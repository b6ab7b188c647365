// Level of detail of a moving 3D view: how many points of a cloud are drawn while the camera
// moves, adapted frame by frame so that a frame takes about kTargetSeconds — every point on a
// fast GPU, a uniform subset under a software renderer. The full cloud is drawn once the camera
// stops.
#pragma once

namespace polarform::studio {

class PointBudget {
 public:
  static constexpr int kMinimum = 20000;
  static constexpr int kInitial = 100000;
  static constexpr double kTargetSeconds = 1.0 / 40.0;

  int points() const { return points_; }
  // After a moving frame that took `seconds` with this budget, for a cloud of `total` points:
  // scales the budget by √(target / seconds), by at most ×1.25 or ×0.8 a frame, and keeps it in
  // [kMinimum, max(total, kMinimum)].
  void adapt(double seconds, int total);

 private:
  int points_ = kInitial;
};

}  // namespace polarform::studio
