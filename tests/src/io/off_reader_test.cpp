// OFF: the header variants (OFF, COFF, NOFF, 4OFF homogeneous, nOFF with a dimension, a missing
// keyword, counts glued to the keyword), comments, and the errors for counts and vertices.
#include "src/io/off_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/src/sample_files.h"

namespace polarform {
namespace {

using io_test::input_error;
using ::testing::HasSubstr;

TEST(OffReader, KeywordVariantsWithExtraColumns) {
  const Eigen::Matrix3Xd expected = io_test::sample_points();
  for (const char* keyword : {"OFF", "COFF", "NOFF", "CNOFF", "STCNOFF"}) {
    SCOPED_TRACE(keyword);
    EXPECT_EQ(parse_off(io_test::sample_off(expected, keyword), "m.off").points, expected);
  }
}

TEST(OffReader, HomogeneousDimensionMissingKeywordAndGluedCounts) {
  const PointCloud homogeneous =
      parse_off("4OFF\n3 1 0\n2 4 6 2\n1 1 1 0.5\n-3 0 3 -1\n3 0 1 2\n", "h.off");
  Eigen::Matrix3Xd expected(3, 3);
  expected << 1, 2, 3, 2, 2, 0, 3, 2, -3;
  EXPECT_EQ(homogeneous.points, expected);
  const PointCloud four_d = parse_off("nOFF\n4\n3 0 0\n1 2 3 9\n4 5 6 9\n7 8 9 9\n", "n.off");
  EXPECT_EQ(four_d.points.col(2), Eigen::Vector3d(7, 8, 9));
  const PointCloud homogeneous_4d =
      parse_off("4nOFF 4\n3 0 0\n1 2 3 9 2\n4 5 6 9 2\n8 8 8 0 4\n", "n.off");
  EXPECT_EQ(homogeneous_4d.points.col(2), Eigen::Vector3d(2, 2, 2));
  const PointCloud bare = parse_off("# no keyword\n3 1 3\n1 2 3\n4 5 6\n7 8 9\n3 0 1 2\n", "b.off");
  EXPECT_EQ(bare.points.col(1), Eigen::Vector3d(4, 5, 6));
  const PointCloud glued = parse_off("OFF3 1 0\n1 2 3\n4 5 6\n7 8 9\n3 0 1 2\n", "g.off");
  EXPECT_EQ(glued.points.col(2), Eigen::Vector3d(7, 8, 9));
}

TEST(OffReader, KeywordMatching) {
  EXPECT_EQ(match_off_keyword("STCN4nOFF")->length, 9u);
  EXPECT_TRUE(match_off_keyword("4OFF")->homogeneous);
  EXPECT_TRUE(match_off_keyword("nOFF 5")->dimension_line);
  EXPECT_FALSE(match_off_keyword("OFF 5")->dimension_line);
  EXPECT_EQ(match_off_keyword("OFF490 518 0")->length, 3u);
  EXPECT_FALSE(match_off_keyword("OFFSET 1 2 3"));
  EXPECT_FALSE(match_off_keyword("1 2 3"));
  EXPECT_FALSE(match_off_keyword("CCOFF"));
}

TEST(OffReader, Errors) {
  EXPECT_THAT(input_error([] { parse_off("OFF\n3 1 0\n1 2 3\n4 5 6\n", "e.off"); }),
              HasSubstr("e.off: line 4: file ends after 2 of the 3 vertices"));
  EXPECT_THAT(input_error([] { parse_off("OFF\n3 1 0\n1 2 3\n4 5 1.0abc\n7 8 9\n", "e.off"); }),
              HasSubstr("e.off: line 4 (vertex 1): invalid number '1.0abc'"));
  EXPECT_THAT(input_error([] { parse_off("OFF\nthree 1 0\n", "e.off"); }),
              HasSubstr("e.off: line 2: expected the counts 'NVertices NFaces NEdges'"));
  EXPECT_THAT(input_error([] { parse_off("OFF BINARY\n", "e.off"); }),
              HasSubstr("e.off: line 1: binary OFF is not supported"));
  EXPECT_THAT(
      input_error([] { parse_off("nOFF\n2\n3 0 0\n", "e.off"); }),
      HasSubstr("e.off: line 2: expected the vertex dimension of nOFF, an integer of at least 3"));
  EXPECT_THAT(input_error([] { parse_off("4OFF\n3 0 0\n1 1 1 1\n1 1 1 0\n1 1 1 1\n", "e.off"); }),
              HasSubstr("e.off: line 4 (vertex 1): homogeneous coordinate is 0"));
  EXPECT_THAT(input_error([] { parse_off("4OFF\n3 0 0\n1 1 1 1\n1 1 1\n1 1 1 1\n", "e.off"); }),
              HasSubstr("e.off: line 4 (vertex 1): expected 4 components, found 3"));
  EXPECT_THAT(input_error([] { parse_off("# only a comment\n", "e.off"); }),
              HasSubstr("e.off: empty OFF file"));
  const PointCloud cloud = parse_off("OFF\n4 0 0\n1 2 3\nnan 0 0\n4 5 6\n7 8 9\n", "e.off",
                                     {.skip_bad = true, .progress = {}});
  EXPECT_EQ(cloud.dropped, 1u);
  EXPECT_EQ(cloud.points.cols(), 3);
}

}  // namespace
}  // namespace polarform
