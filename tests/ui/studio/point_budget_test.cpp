// The moving 3D view's level of detail: with a frame time linear in the points drawn, the budget
// settles where a frame takes the target time; a fast renderer gets every point, a slow one the
// minimum, and no frame changes the budget by more than the damping allows.
#include "ui/studio/point_budget.h"

#include <gtest/gtest.h>

namespace polarform::studio {
namespace {

// Frames of `fixed` seconds plus `per_point` seconds per point drawn, until the budget settles.
int settle(double fixed, double per_point, int total, int frames = 200) {
  PointBudget budget;
  for (int i = 0; i < frames; ++i) budget.adapt(fixed + per_point * budget.points(), total);
  return budget.points();
}

TEST(PointBudget, SettlesWhereFramesTakeTheTarget) {
  // The fit workspace under llvmpipe: ~17 ms of UI and surface, 0.13 µs per point.
  const double fixed = 0.017, per_point = 0.13e-6;
  const int points = settle(fixed, per_point, 1000000);
  const double settled = fixed + per_point * points;
  EXPECT_NEAR(settled, PointBudget::kTargetSeconds, 0.02 * PointBudget::kTargetSeconds) << points;
}

TEST(PointBudget, FastRenderersDrawEveryPointSlowOnesTheMinimum) {
  EXPECT_EQ(settle(0.002, 1e-9, 1000000), 1000000);
  EXPECT_EQ(settle(0.002, 1e-9, 5000), PointBudget::kMinimum);  // clouds below the minimum: all
  EXPECT_EQ(settle(0.060, 1e-7, 1000000), PointBudget::kMinimum);
}

TEST(PointBudget, ChangesAreDamped) {
  PointBudget budget;
  budget.adapt(10.0, 1000000);  // a very slow frame
  EXPECT_EQ(budget.points(), static_cast<int>(0.8 * PointBudget::kInitial));
  budget.adapt(1e-6, 1000000);  // a very fast one
  EXPECT_EQ(budget.points(), static_cast<int>(1.25 * 0.8 * PointBudget::kInitial));
  budget.adapt(0.0, 1000000);  // no timing yet: unchanged
  EXPECT_EQ(budget.points(), static_cast<int>(1.25 * 0.8 * PointBudget::kInitial));
}

}  // namespace
}  // namespace polarform::studio
