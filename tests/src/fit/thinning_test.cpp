// Thinning by blanket vertices (spec P7): at most one point per vertex, more points as the
// blanket gets finer, nearest points equal to brute force, the rings searched.
#include "src/fit/thinning.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "src/error.h"
#include "tests/src/fit/fit_test_support.h"
#include "tests/src/fit/patch_test_support.h"

namespace polarform {
namespace {

// The union of the brute-force nearest points (ties by the smaller index) of all vertices.
std::vector<int> brute_force_kept(const Eigen::Matrix3Xd& points, const SurfaceBlanket& b) {
  std::set<int> kept;
  for (Eigen::Index k = 0; k < b.points.cols(); ++k) {
    Eigen::Index best = 0;
    (points.colwise() - b.points.col(k)).colwise().squaredNorm().minCoeff(&best);
    kept.insert(static_cast<int>(best));
  }
  return {kept.begin(), kept.end()};
}

// P7.1 and P7.4 on S8(a): nested blankets (9, 17, 33, 65 vertices a side) stand for decreasing
// thinning tolerances; every kept set equals brute force.
TEST(Thinning, KeptGrowsWithFinerBlanketsAndMatchesBruteForce) {
  const NurbsSurface s = test::bulged_quarter();
  const test::Samples data = test::sample_surface(s, 11517, 41);
  std::size_t previous = 0;
  for (int n : {9, 17, 33, 65}) {
    const SurfaceBlanket b = test::uniform_blanket(s, n, n);
    const Thinning t = thin_by_blanket(data.points, b);
    EXPECT_EQ(t.vertices, n * n);
    EXPECT_LE(static_cast<int>(t.kept.size()), t.vertices);
    EXPECT_GE(t.kept.size(), previous);
    EXPECT_TRUE(std::is_sorted(t.kept.begin(), t.kept.end()));
    EXPECT_EQ(t.kept, brute_force_kept(data.points, b)) << n;
    EXPECT_LE(t.mean_rings, 2.0);
    previous = t.kept.size();
    RecordProperty("kept_" + std::to_string(n), static_cast<int>(t.kept.size()));
    RecordProperty("mean_rings_" + std::to_string(n), test::sci(t.mean_rings));
  }
}

TEST(Thinning, RejectsEmptyInput) {
  const SurfaceBlanket b = test::uniform_blanket(test::bulged_quarter(), 3, 3);
  EXPECT_THROW(thin_by_blanket(Eigen::Matrix3Xd(3, 0), b), InputError);
}

}  // namespace
}  // namespace polarform
