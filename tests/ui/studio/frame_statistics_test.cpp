// Frame statistics for --bench-frames: nearest-rank median and p95, mean, min and max of known
// samples, the count of frames over budget, and the printed summary.
#include "ui/studio/frame_statistics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace polarform::studio {
namespace {

TEST(FrameStatistics, SummaryOfKnownSamples) {
  std::vector<double> ms;
  for (int i = 100; i >= 1; --i) ms.push_back(i);  // 1..100 ms, unsorted
  const TimeSummary s = summarize(ms);
  EXPECT_DOUBLE_EQ(s.mean, 50.5);
  EXPECT_DOUBLE_EQ(s.median, 50.0);
  EXPECT_DOUBLE_EQ(s.p95, 95.0);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 100.0);
}

TEST(FrameStatistics, OneSampleAndNone) {
  const TimeSummary one = summarize({7.5});
  EXPECT_EQ(one.mean, 7.5);
  EXPECT_EQ(one.median, 7.5);
  EXPECT_EQ(one.p95, 7.5);
  const TimeSummary none = summarize({});
  EXPECT_EQ(none.mean, 0.0);
  EXPECT_EQ(none.max, 0.0);
}

TEST(FrameStatistics, CountsFramesOverBudgetAndPrintsEveryPart) {
  FrameStatistics stats;
  stats.add({.frame = 10.0, .compute = 2.0, .ui = 3.0, .render = 5.0});
  stats.add({.frame = 20.0, .compute = 4.0, .ui = 6.0, .render = 10.0});
  stats.add({.frame = 16.0, .compute = 1.0, .ui = 1.0, .render = 14.0});
  EXPECT_EQ(stats.frames(), 3u);
  EXPECT_EQ(stats.frames_over(1000.0 / 60.0), 1u);
  EXPECT_EQ(stats.frames_over(15.0), 2u);
  EXPECT_NEAR(stats.frame_times().mean, 46.0 / 3.0, 1e-12);
  const std::string text = stats.text();
  EXPECT_THAT(text, testing::HasSubstr("frames: 3\n"));
  EXPECT_THAT(text, testing::HasSubstr("frame time: mean 15.33 ms, median 16.00 ms, p95 20.00 ms"));
  EXPECT_THAT(text, testing::HasSubstr("recompute time: mean 2.33 ms"));
  EXPECT_THAT(text, testing::HasSubstr("ui time: mean 3.33 ms"));
  EXPECT_THAT(text, testing::HasSubstr("render time: mean 9.67 ms"));
  EXPECT_THAT(text, testing::HasSubstr("frames over 16.7 ms: 1\n"));
}

}  // namespace
}  // namespace polarform::studio
