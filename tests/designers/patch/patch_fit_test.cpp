// The patch pipeline (Piegl & Tiller 2001, spec P8) on patches with a known answer: a bicubic
// Coons patch of four cubic boundaries (its own bilinear base: parameters and net come back
// exactly), the same with noise, the S8 set with correction rounds, thinning, and the structured
// 250° grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "designers/patch/boundary_input.h"
#include "designers/patch/patch_fit.h"
#include "src/nurbs/coons_surface.h"
#include "src/nurbs/point_inversion.h"
#include "tests/support/src/synthetic_patches.h"

namespace polarform {
namespace {

using patch_test::exact_boundary;
using patch_test::s8_patch;
using patch_test::sample_patch;

double diagonal(const NurbsSurface& s) {
  Eigen::Vector3d lo = s.control_point(0, 0), hi = lo;
  for (int i = 0; i < s.size_u(); ++i)
    for (int j = 0; j < s.size_v(); ++j) {
      lo = lo.cwiseMin(s.control_point(i, j));
      hi = hi.cwiseMax(s.control_point(i, j));
    }
  return (hi - lo).norm();
}

// rms and max of the distances from a 41 × 41 grid on `truth` to `fit`.
std::pair<double, double> truth_to_fit(const NurbsSurface& truth, const NurbsSurface& fit) {
  const SurfaceProjector projector(fit);
  double sum = 0.0, max = 0.0;
  for (int a = 0; a <= 40; ++a)
    for (int b = 0; b <= 40; ++b) {
      const double d = projector.project(truth.point(a / 40.0, b / 40.0)).distance;
      sum += d * d;
      max = std::max(max, d);
    }
  return {std::sqrt(sum / (41 * 41)), max};
}

TEST(PatchFit, ACoonsPatchOfItsBoundaryComesBackExactly) {
  // The bilinear Coons patch of four cubic curves is a bicubic patch and its own base: polished
  // parameters are the true ones and the fixed-boundary 4 × 4 fit reproduces its net.
  const PatchBoundary boundary = exact_boundary(s8_patch('a'));
  const NurbsSurface truth = bilinear_coons(boundary);
  const auto sample = sample_patch(truth, 2000);
  const PatchFit r = fit_patch(sample.points, boundary, PatchFitOptions{});
  EXPECT_LT((r.parameters.u - sample.u).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((r.parameters.v - sample.v).cwiseAbs().maxCoeff(), 1e-9);
  ASSERT_EQ(r.fit.surface.size_u(), 4);
  ASSERT_EQ(r.fit.surface.size_v(), 4);
  const double size = diagonal(truth);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      EXPECT_LT((r.fit.surface.control_point(i, j) - truth.control_point(i, j)).norm(), 1e-9 * size);
  EXPECT_LT(r.error.max, 1e-9 * size);
  EXPECT_EQ(r.error.count, 2000u);
}

TEST(PatchFit, WithNoiseTheTruthToFitRmsIsBelowTheNoise) {
  const PatchBoundary boundary = exact_boundary(s8_patch('c'));
  const NurbsSurface truth = bilinear_coons(boundary);
  const double sigma = 1e-3 * diagonal(truth);
  const auto sample = sample_patch(truth, 5000, sigma);
  const PatchFit r = fit_patch(sample.points, boundary, PatchFitOptions{});
  const auto [rms, max] = truth_to_fit(truth, r.fit.surface);
  EXPECT_LE(rms, sigma) << "max " << max;
  EXPECT_NEAR(r.error.rms, sigma, 0.1 * sigma);  // the residual is the noise
}

TEST(PatchFit, TheDataChooseTheNetOfNoisyModelPatches) {
  // Gently and strongly curved 8 × 8 patches, moved rigidly, with noise σ and their exact
  // boundaries: the net grows from the boundary's until GCV stops improving; the surface stays
  // within the noise of the truth.
  for (const double bend : {0.0, 1.5}) {
    const NurbsSurface truth = patch_test::wavy_patch(bend);
    const double sigma = 1e-3 * diagonal(truth);
    const auto sample = sample_patch(truth, 20000, sigma, 11);
    PatchFitOptions o;
    o.correction_rounds = 3;
    const PatchFit r = fit_patch(sample.points, patch_test::net_boundary(truth), o);
    ASSERT_TRUE(r.net.has_value());
    EXPECT_GT(r.net->candidates.size(), 1u);
    const auto [rms, max] = truth_to_fit(truth, r.fit.surface);
    EXPECT_LE(rms, sigma) << "bend " << bend << ": net " << r.net->control_u << " × "
                          << r.net->control_v << ", " << r.net->stop;
    EXPECT_LE(max, 5 * sigma) << "bend " << bend;
    EXPECT_NEAR(r.net->noise, sigma, 0.2 * sigma);  // the residual is the noise
  }
}

TEST(PatchFit, TheS8SetWithinAThousandthOfTheDiagonal) {
  // Bilinear Coons base for (a)–(c), the tensor-product base for (d) and (e), where the bilinear
  // patch misses the interior; 5 correction rounds; the 4 × 4 bicubic net can represent each.
  for (const char id : {'a', 'b', 'c', 'd', 'e'}) {
    const NurbsSurface truth = s8_patch(id);
    const auto sample = sample_patch(truth, 11517);
    PatchFitOptions o;
    o.correction_rounds = 5;
    if (id == 'd' || id == 'e') o.base.kind = BaseKind::tensor;
    const PatchFit r = fit_patch(sample.points, exact_boundary(truth), o);
    const double size = diagonal(truth);
    EXPECT_LE(r.error.max, 1e-3 * size) << id << ": round 0 max " << r.fit.rounds[0].max_distance;
    for (std::size_t k = 1; k < r.fit.rounds.size(); ++k)
      EXPECT_LE(r.fit.rounds[static_cast<std::size_t>(r.fit.best_round)].max_distance,
                r.fit.rounds[k].max_distance + 1e-15)
          << id;
  }
}

TEST(PatchFit, ThinningAtATenthOfAPercentKeepsTheMaxErrorWithin1Point1Times) {
  const PatchBoundary boundary = exact_boundary(s8_patch('a'));
  const NurbsSurface truth = bilinear_coons(boundary);
  const double sigma = 1e-4 * diagonal(truth);
  const auto sample = sample_patch(truth, 11517, sigma);
  PatchFitOptions all;
  const PatchFit full = fit_patch(sample.points, boundary, all);
  PatchFitOptions thin = all;
  thin.thin = 0.001;
  const PatchFit thinned = fit_patch(sample.points, boundary, thin);
  ASSERT_TRUE(thinned.thinning.has_value());
  EXPECT_LT(thinned.thinning->kept.size(), 11517u);
  EXPECT_EQ(thinned.error.count, 11517u);  // measured over all points
  EXPECT_LE(thinned.error.max, 1.1 * full.error.max)
      << "kept " << thinned.thinning->kept.size() << " of 11517";
}

TEST(PatchFit, AStructuredGridOver250DegreesKeepsItsRowsAndColumnsInOrder) {
  const int rows = 40, cols = 40;
  const Eigen::Matrix3Xd grid = patch_test::s9_grid(rows, cols, 1e-3 * 2.6);
  const StructuredGrid g = split_structured_grid(grid, rows, cols);
  const FittedBoundary b = fit_boundary_polylines(g.polylines);
  Eigen::Matrix3Xd inside(3, static_cast<Eigen::Index>(g.inside.size()));
  for (std::size_t k = 0; k < g.inside.size(); ++k)
    inside.col(static_cast<Eigen::Index>(k)) = grid.col(g.inside[k]);
  PatchFitOptions o;
  o.control_u = o.control_v = 16;
  const PatchFit r = fit_patch(inside, b.boundary, o);
  // Inside point (row, col) is entry (row − 1)·(cols − 2) + col − 1; u runs along columns.
  int inversions = 0;
  const auto at = [&](const Eigen::VectorXd& x, int row, int col) {
    return x[(row - 1) * (cols - 2) + col - 1];
  };
  for (int row = 1; row + 1 < rows; ++row)
    for (int col = 1; col + 2 < cols; ++col) inversions += at(r.u, row, col + 1) <= at(r.u, row, col);
  for (int col = 1; col + 1 < cols; ++col)
    for (int row = 1; row + 2 < rows; ++row) inversions += at(r.v, row + 1, col) <= at(r.v, row, col);
  EXPECT_EQ(inversions, 0);
  EXPECT_LT(r.error.rms, 3 * 2.6e-3);
}

}  // namespace
}  // namespace polarform
