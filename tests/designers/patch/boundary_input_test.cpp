// The boundary of a patch from four polylines (oriented, corners snapped, B1 fits) and from the
// border of a structured grid.
#include "designers/patch/boundary_input.h"

#include <gtest/gtest.h>

#include "src/error.h"
#include "src/fit/curve_distance.h"
#include "tests/support/src/synthetic_patches.h"

namespace polarform {
namespace {

using patch_test::boundary_polylines;
using patch_test::s8_patch;

TEST(BoundaryInput, OrientsReversedPolylinesAndFitsThemWithinTheTolerance) {
  const NurbsSurface s = s8_patch('a');
  std::array<Eigen::Matrix3Xd, 4> p = boundary_polylines(s, 200);
  p[1] = p[1].rowwise().reverse().eval();
  p[3] = p[3].rowwise().reverse().eval();
  BoundaryFitOptions o;
  o.tolerance = 1e-6;
  const FittedBoundary b = fit_boundary_polylines(p, o);
  EXPECT_EQ(b.reversed, (std::array<bool, 4>{false, true, false, true}));
  for (int k = 0; k < 4; ++k) {
    EXPECT_LE(b.max_distance[k], 1e-6) << k;
    EXPECT_LT(b.corner_gap[k], 1e-12) << k;
  }
  // The curves follow the true edges; the parametrisation along them is chord length, not the
  // patch's, so compare as point sets through the corners and the shape.
  EXPECT_LT((b.boundary.u0.point(0) - s.point(0, 0)).norm(), 1e-12);
  EXPECT_LT((b.boundary.u1.point(1) - s.point(1, 1)).norm(), 1e-12);
  EXPECT_LT((b.boundary.v1.point(0) - s.point(1, 0)).norm(), 1e-12);
  EXPECT_LT((b.boundary.v0.point(1) - s.point(0, 1)).norm(), 1e-12);
  // The fitted curve runs along the true edge (at another speed: chord-length parameters).
  const CurveDistance<3> to_fit(b.boundary.u0);
  double away = 0.0;
  for (int k = 0; k <= 1000; ++k)
    away = std::max(away, to_fit.project(s.point(k / 1000.0, 0)).distance);
  EXPECT_LE(away, 1e-6);
}

TEST(BoundaryInput, AWholeLoopGivenBackwardsIsTurned) {
  const NurbsSurface s = s8_patch('c');
  const std::array<Eigen::Matrix3Xd, 4> p = boundary_polylines(s, 50);
  std::array<Eigen::Matrix3Xd, 4> back;
  for (int k = 0; k < 4; ++k) back[static_cast<std::size_t>(k)] = p[static_cast<std::size_t>(3 - k)].rowwise().reverse();
  const FittedBoundary b = fit_boundary_polylines(back);
  for (int k = 0; k < 4; ++k) EXPECT_LT(b.corner_gap[k], 1e-12);
}

TEST(BoundaryInput, ACornerGapIsRefusedByName) {
  const NurbsSurface s = s8_patch('c');
  std::array<Eigen::Matrix3Xd, 4> p = boundary_polylines(s, 50);
  p[2].colwise() += Eigen::Vector3d(0, 0, 1.0);
  try {
    fit_boundary_polylines(p);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("boundary corner 2 (where curve 2 starts): the curves' "
                                         "ends are 1 mm apart"),
              std::string::npos)
        << e.what();
  }
}

TEST(BoundaryInput, StructuredGridBorderAndInside) {
  Eigen::Matrix3Xd g(3, 4 * 5);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 5; ++c) g.col(r * 5 + c) = Eigen::Vector3d(c, r, 0.1 * r * c);
  const StructuredGrid s = split_structured_grid(g, 4, 5);
  EXPECT_EQ(s.inside, (std::vector<int>{6, 7, 8, 11, 12, 13}));
  EXPECT_EQ(s.polylines[0].col(4), Eigen::Vector3d(4, 0, 0));
  EXPECT_TRUE(s.polylines[1].col(3).isApprox(Eigen::Vector3d(4, 3, 1.2), 1e-15));
  EXPECT_EQ(s.polylines[2].col(4), Eigen::Vector3d(0, 3, 0));
  EXPECT_EQ(s.polylines[3].col(3), Eigen::Vector3d(0, 0, 0));
  EXPECT_THROW(split_structured_grid(g, 5, 4 + 1), InputError);
  EXPECT_THROW(split_structured_grid(g, 2, 10), InputError);
}

}  // namespace
}  // namespace polarform
