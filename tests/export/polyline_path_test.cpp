// Pixel polylines: gaps at non-finite points, M4 decimation keeps extremes, clipping, path text.
#include "export/polyline_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace polarform {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(PolylinePath, NonFinitePointsSplitRuns) {
  const Polyline points = {{0, 0}, {1, 1}, {kNaN, 2}, {3, 3}, {4, kInf}, {5, 5}, {6, 6}, {7, 7}};
  const std::vector<Polyline> runs = finite_runs(points);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0], (Polyline{{0, 0}, {1, 1}}));
  EXPECT_EQ(runs[1], (Polyline{{3, 3}}));
  EXPECT_EQ(runs[2], (Polyline{{5, 5}, {6, 6}, {7, 7}}));
  EXPECT_TRUE(finite_runs(Polyline{{kNaN, kNaN}}).empty());
}

TEST(PolylinePath, DecimationKeepsFirstLastAndExtremesOfEveryColumn) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 1);
  Polyline run;
  const int n = 100000;  // 1000 points per pixel column over 100 columns
  for (int i = 0; i < n; ++i) run.push_back({100.0 * i / n, 50 + noise(rng)});
  run[54321].y = -400;  // a one-sample spike up (SVG y points down) ...
  run[77777].y = 900;   // ... and one down
  const Polyline kept = decimate_to_columns(run);
  EXPECT_LE(kept.size(), 4u * 100u);
  EXPECT_GE(kept.size(), 2u * 100u);
  EXPECT_EQ(kept.front(), run.front());
  EXPECT_EQ(kept.back(), run.back());
  for (int column = 0; column < 100; ++column) {
    double lo = kInf, hi = -kInf, kept_lo = kInf, kept_hi = -kInf;
    for (const PixelPoint& p : run)
      if (std::floor(p.x) == column) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
    for (const PixelPoint& p : kept)
      if (std::floor(p.x) == column)
        kept_lo = std::min(kept_lo, p.y), kept_hi = std::max(kept_hi, p.y);
    ASSERT_EQ(kept_lo, lo) << "column " << column;
    ASSERT_EQ(kept_hi, hi) << "column " << column;
  }
  // Order is preserved: x never decreases along the decimated run of a monotone input.
  for (std::size_t i = 1; i < kept.size(); ++i) ASSERT_LE(kept[i - 1].x, kept[i].x);
}

TEST(PolylinePath, ClippingCutsAtTheRectangle) {
  const PixelRect rect{0, 0, 10, 10};
  PixelPoint a{-5, 5}, b{5, 5};
  ASSERT_TRUE(clip_segment(a, b, rect));
  EXPECT_EQ(a, (PixelPoint{0, 5}));
  EXPECT_EQ(b, (PixelPoint{5, 5}));
  PixelPoint c{-5, -5}, d{15, 15};
  ASSERT_TRUE(clip_segment(c, d, rect));
  EXPECT_EQ(c, (PixelPoint{0, 0}));
  EXPECT_EQ(d, (PixelPoint{10, 10}));
  PixelPoint e{11, 0}, f{20, 10};
  EXPECT_FALSE(clip_segment(e, f, rect));

  // In, out above, back in: two pieces, cut exactly at y = 0.
  const Polyline run = {{1, 5}, {3, -5}, {5, 5}, {7, 5}};
  const std::vector<Polyline> pieces = clip_polyline(run, rect);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0], (Polyline{{1, 5}, {2, 0}}));
  EXPECT_EQ(pieces[1], (Polyline{{4, 0}, {5, 5}, {7, 5}}));
  EXPECT_EQ(clip_polyline(Polyline{{3, 3}}, rect).size(), 1u);
  EXPECT_TRUE(clip_polyline(Polyline{{30, 3}}, rect).empty());
}

TEST(PolylinePath, PathDataHasOneMovePerPieceAndTwoDecimals) {
  const std::vector<Polyline> pieces = {{{1, 2.005}, {3.14159, 4}}, {{5.5, -0.001}}};
  EXPECT_EQ(path_data(pieces), "M1 2L3.14 4M5.5 0L5.5 0");
}

}  // namespace
}  // namespace polarform
