// Segment edits: adding, deleting, reordering segments and moving a boundary keep the program
// covering [0°, 360°] without gaps or overlaps, keep every width at least kMinSegmentWidth, and an
// edit that cannot be made throws InputError with a message and changes nothing.
#include "ui/studio/segment_edits.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "src/error.h"
#include "src/units.h"

namespace polarform::studio {
namespace {

SegmentSpec segment(SegmentKind kind, double start_deg, double end_deg, double lift) {
  SegmentSpec s;
  s.kind = kind;
  s.start = start_deg * kRadiansPerDegree;
  s.end = end_deg * kRadiansPerDegree;
  s.lift = lift;
  return s;
}

// Rise 0–120°, dwell 120–180°, return 180–300°, dwell 300–360°.
std::vector<SegmentSpec> program() {
  return {segment(SegmentKind::Rise, 0, 120, 10), segment(SegmentKind::Dwell, 120, 180, 0),
          segment(SegmentKind::Return, 180, 300, 10), segment(SegmentKind::Dwell, 300, 360, 0)};
}

// The segments tile [0, 2π]: contiguous boundaries, each at least kMinSegmentWidth wide.
void expect_covers_full_turn(const std::vector<SegmentSpec>& s) {
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.front().start, 0.0);
  EXPECT_NEAR(s.back().end, 2.0 * std::numbers::pi, 1e-12);
  double total = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_GE(s[i].end - s[i].start, kMinSegmentWidth * (1.0 - 1e-12)) << "segment " << i + 1;
    if (i + 1 < s.size()) {
      EXPECT_EQ(s[i].end, s[i + 1].start) << "boundary " << i + 1;
    }
    total += s[i].end - s[i].start;
  }
  EXPECT_NEAR(total, 2.0 * std::numbers::pi, 1e-12);
}

// Runs an edit that must be refused: InputError whose message contains `words`, no change.
template <class Edit>
void expect_refused(std::vector<SegmentSpec> segments, Edit edit, const char* words) {
  const std::vector<SegmentSpec> before = segments;
  try {
    edit(segments);
    ADD_FAILURE() << "the edit was accepted; expected a message containing '" << words << "'";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), testing::HasSubstr(words));
  }
  EXPECT_EQ(segments, before);
}

TEST(SegmentEdits, MovingABoundaryKeepsTheTurnCovered) {
  auto s = program();
  EXPECT_DOUBLE_EQ(set_boundary(s, 1, 100 * kRadiansPerDegree), 100 * kRadiansPerDegree);
  EXPECT_EQ(s[0].end, 100 * kRadiansPerDegree);
  EXPECT_EQ(s[1].start, 100 * kRadiansPerDegree);
  EXPECT_EQ(s[0].start, 0.0);
  EXPECT_EQ(s[1].end, 180 * kRadiansPerDegree);
  expect_covers_full_turn(s);
}

TEST(SegmentEdits, BoundaryIsClampedToLeaveTheMinimumWidth) {
  auto s = program();
  EXPECT_DOUBLE_EQ(set_boundary(s, 2, 500 * kRadiansPerDegree),
                   300 * kRadiansPerDegree - kMinSegmentWidth);
  EXPECT_NEAR(s[2].end - s[2].start, kMinSegmentWidth, 1e-15);
  expect_covers_full_turn(s);
  EXPECT_DOUBLE_EQ(set_boundary(s, 2, -1.0), 120 * kRadiansPerDegree + kMinSegmentWidth);
  EXPECT_NEAR(s[1].end - s[1].start, kMinSegmentWidth, 1e-15);
  expect_covers_full_turn(s);
}

TEST(SegmentEdits, MissingBoundaryIsRefused) {
  expect_refused(program(), [](auto& s) { set_boundary(s, 0, 1.0); }, "no boundary 0");
  expect_refused(program(), [](auto& s) { set_boundary(s, 4, 1.0); }, "no boundary 4");
}

TEST(SegmentEdits, AddDwellSplitsTheSegmentInHalves) {
  auto s = program();
  EXPECT_EQ(insert_dwell_after(s, 0), 1);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_EQ(s[0].kind, SegmentKind::Rise);
  EXPECT_DOUBLE_EQ(s[0].end, 60 * kRadiansPerDegree);
  EXPECT_EQ(s[1].kind, SegmentKind::Dwell);
  EXPECT_EQ(s[1].lift, 0.0);
  EXPECT_DOUBLE_EQ(s[1].end, 120 * kRadiansPerDegree);
  expect_covers_full_turn(s);
  EXPECT_EQ(insert_dwell_after(s, 4), 5);  // after the last one too
  EXPECT_DOUBLE_EQ(s[5].start, 330 * kRadiansPerDegree);
  expect_covers_full_turn(s);
}

TEST(SegmentEdits, AddDwellRefusesASegmentTooNarrowToSplit) {
  auto s = program();
  set_boundary(s, 2, 120 * kRadiansPerDegree);  // segment 2 shrinks to the minimum width
  expect_refused(s, [](auto& v) { insert_dwell_after(v, 1); }, "splitting it would leave parts");
  expect_refused(s, [](auto& v) { insert_dwell_after(v, 4); }, "no segment 5 (the cam has 4)");
  expect_refused(s, [](auto& v) { insert_dwell_after(v, -1); }, "no segment 0");
}

TEST(SegmentEdits, DeleteGivesTheSpanToTheNeighbour) {
  auto s = program();
  delete_segment(s, 1);  // the previous segment takes it
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].end, 180 * kRadiansPerDegree);
  expect_covers_full_turn(s);
  delete_segment(s, 0);  // the first: the next takes it
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].kind, SegmentKind::Return);
  EXPECT_EQ(s[0].start, 0.0);
  expect_covers_full_turn(s);
  delete_segment(s, 1);  // the last
  ASSERT_EQ(s.size(), 1u);
  expect_covers_full_turn(s);
}

TEST(SegmentEdits, DeleteRefusesTheOnlySegmentAndMissingOnes) {
  expect_refused({segment(SegmentKind::Dwell, 0, 360, 0)}, [](auto& s) { delete_segment(s, 0); },
                 "at least one segment");
  expect_refused(program(), [](auto& s) { delete_segment(s, 7); }, "no segment 8");
}

TEST(SegmentEdits, ReorderSwapsNeighboursEachKeepingItsWidth) {
  auto s = program();
  EXPECT_EQ(move_segment(s, 1, +1), 2);  // the 60° dwell after the 120° return
  EXPECT_EQ(s[1].kind, SegmentKind::Return);
  EXPECT_DOUBLE_EQ(s[1].start, 120 * kRadiansPerDegree);
  EXPECT_DOUBLE_EQ(s[1].end, 240 * kRadiansPerDegree);
  EXPECT_EQ(s[2].kind, SegmentKind::Dwell);
  EXPECT_DOUBLE_EQ(s[2].end - s[2].start, 60 * kRadiansPerDegree);
  expect_covers_full_turn(s);
  EXPECT_EQ(move_segment(s, 2, -1), 1);  // and back: the original program
  const auto original = program();
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(s[i].kind, original[i].kind);
    EXPECT_NEAR(s[i].start, original[i].start, 1e-12);
    EXPECT_NEAR(s[i].end, original[i].end, 1e-12);
  }
}

TEST(SegmentEdits, ReorderRefusesMovesPastEitherEnd) {
  expect_refused(program(), [](auto& s) { move_segment(s, 0, -1); }, "segment 1 is already first");
  expect_refused(program(), [](auto& s) { move_segment(s, 3, +1); }, "segment 4 is already last");
  expect_refused(program(), [](auto& s) { move_segment(s, 1, 2); }, "direction");
  expect_refused(program(), [](auto& s) { move_segment(s, 9, -1); }, "no segment 10");
}

TEST(SegmentEdits, ManyRandomEditsKeepTheTurnCovered) {
  auto s = program();
  for (int step = 0; step < 400; ++step) {
    const int n = static_cast<int>(s.size());
    const int i = (step * 7) % n;
    switch (step % 4) {
      case 0:
        if (s[i].end - s[i].start >= 2 * kMinSegmentWidth) insert_dwell_after(s, i);
        break;
      case 1:
        if (n > 3) delete_segment(s, i);
        break;
      case 2:
        if (i + 1 < n) move_segment(s, i, +1);
        break;
      case 3:
        if (n > 1) set_boundary(s, 1 + i % (n - 1), (step * 37 % 360) * kRadiansPerDegree);
        break;
    }
    expect_covers_full_turn(s);
    if (HasFailure()) FAIL() << "after step " << step;
  }
}

TEST(SegmentEdits, KindChangeSetsTheLift) {
  SegmentSpec s = segment(SegmentKind::Dwell, 0, 90, 0);
  set_kind(s, SegmentKind::Rise, 12.5);
  EXPECT_EQ(s.kind, SegmentKind::Rise);
  EXPECT_EQ(s.lift, 12.5);
  s.lift = 3.0;
  set_kind(s, SegmentKind::Return, 12.5);  // a rise becoming a return keeps its lift
  EXPECT_EQ(s.lift, 3.0);
  set_kind(s, SegmentKind::Dwell, 12.5);
  EXPECT_EQ(s.lift, 0.0);
}

}  // namespace
}  // namespace polarform::studio
