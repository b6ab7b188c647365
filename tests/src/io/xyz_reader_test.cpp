// Delimited-text clouds: blanks and commas, header lines, comments, extra columns, the .pts count
// line, and the errors (with line numbers) for bad numbers, NaN, missing fields, decimal commas.
#include "src/io/xyz_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/io/point_cloud.h"
#include "tests/support/src/sample_files.h"

namespace polarform {
namespace {

using io_test::input_error;
using ::testing::HasSubstr;

TEST(XyzReader, BlankSeparatedWithHeaderCommentAndExtraColumn) {
  const Eigen::Matrix3Xd expected = io_test::sample_points();
  const PointCloud cloud = parse_xyz(io_test::sample_xyz(expected, false), "scan.xyz");
  EXPECT_EQ(cloud.points.cols(), 6);
  EXPECT_EQ(cloud.dropped, 0u);
  EXPECT_EQ(cloud.points, expected);
}

TEST(XyzReader, CommaSeparatedWithHeaderAndCrlf) {
  const Eigen::Matrix3Xd expected = io_test::sample_points();
  const PointCloud cloud = parse_xyz(io_test::sample_xyz(expected, true), "scan.csv");
  EXPECT_EQ(cloud.points, expected);
}

TEST(XyzReader, SignsExponentsTrailingCommentsBomAndPtsCount) {
  const std::string text =
      "\xEF\xBB\xBF"
      "3\n"
      "+1.5 -2e-3 .25 # first\n"
      "  1E2,2.,-0 ,label\n"
      "\n"
      "7 8 9 0 255 255 255\n";
  const PointCloud cloud = parse_xyz(text, "scan.pts");
  ASSERT_EQ(cloud.points.cols(), 3);
  EXPECT_EQ(cloud.points.col(0), Eigen::Vector3d(1.5, -0.002, 0.25));
  EXPECT_EQ(cloud.points.col(1), Eigen::Vector3d(100.0, 2.0, 0.0));
  EXPECT_EQ(cloud.points.col(2), Eigen::Vector3d(7, 8, 9));
}

TEST(XyzReader, BadNumberNamesFileLineAndToken) {
  const std::string message =
      input_error([] { parse_xyz("x y z\n1 2 3\n4 5 6\n7 8 1.0abc\n", "scan.xyz"); });
  EXPECT_THAT(message, HasSubstr("scan.xyz: line 4: invalid number '1.0abc'"));
  EXPECT_THAT(message, HasSubstr("expected z"));
}

TEST(XyzReader, BadNumberOnTheFirstLineIsNotTakenForAHeader) {
  EXPECT_THAT(input_error([] { parse_xyz("1.0abc 2 3\n1 2 3\n", "a.xyz"); }),
              HasSubstr("a.xyz: line 1: invalid number '1.0abc'"));
}

TEST(XyzReader, TextAfterTheDataIsAnError) {
  EXPECT_THAT(input_error([] { parse_xyz("1 2 3\n4 5 6\nsix 7 8\n", "a.txt"); }),
              HasSubstr("a.txt: line 3: invalid number 'six': expected x"));
}

TEST(XyzReader, NanAndInfinityAreErrors) {
  EXPECT_THAT(input_error([] { parse_xyz("1 2 3\n4 nan 6\n7 8 9\n", "a.xyz"); }),
              HasSubstr("a.xyz: line 2: y is NaN or infinite"));
  EXPECT_THAT(input_error([] { parse_xyz("nan 2 3\n4 5 6\n7 8 9\n", "a.xyz"); }),
              HasSubstr("a.xyz: line 1: x is NaN or infinite"));
  EXPECT_THAT(input_error([] { parse_xyz("1 2 3\n4 5 6\n7 8 -inf\n", "a.xyz"); }),
              HasSubstr("a.xyz: line 3: z is NaN or infinite"));
  EXPECT_THAT(input_error([] { parse_xyz("1 2 3\n4 5 1e999\n7 8 9\n", "a.xyz"); }),
              HasSubstr("a.xyz: line 2: invalid number '1e999'"));
}

TEST(XyzReader, MissingFieldsAndDecimalCommas) {
  EXPECT_THAT(input_error([] { parse_xyz("1 2 3\n4 5\n", "a.xyz"); }),
              HasSubstr("a.xyz: line 2: expected 3 coordinates x y z, found 2"));
  EXPECT_THAT(input_error([] { parse_xyz("1,,3\n", "a.csv"); }),
              HasSubstr("a.csv: line 1: invalid number ''"));
  EXPECT_THAT(input_error([] { parse_xyz("1,5 2,5 3,5\n", "a.csv"); }),
              HasSubstr("a.csv: line 1: expected ',' before z, found '2' (decimal commas"));
  EXPECT_THAT(input_error([] { parse_xyz("1 2,3\n", "a.csv"); }),
              HasSubstr("a.csv: line 1: unexpected ','"));
}

TEST(XyzReader, SkipBadDropsAndCountsBadLines) {
  const std::string text =
      "x y z\n"
      "1 2 3\n"
      "4 5 1.0abc\n"
      "4 5 6\n"
      "nan 0 0\n"
      "7 8\n"
      "7 8 9\n"
      "10 11 12\n";
  const PointCloud cloud = parse_xyz(text, "a.xyz", {.skip_bad = true, .progress = {}});
  EXPECT_EQ(cloud.dropped, 3u);
  ASSERT_EQ(cloud.points.cols(), 4);
  EXPECT_EQ(cloud.points.col(1), Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(cloud.points.col(3), Eigen::Vector3d(10, 11, 12));
}

TEST(XyzReader, FewerThanThreePoints) {
  EXPECT_THAT(input_error([] { parse_xyz("1 2 3\n1 2 3\n", "a.xyz"); }),
              HasSubstr("a.xyz: needs at least 3 points, found 2"));
  EXPECT_THAT(input_error([] { parse_xyz("x y z\n# nothing\n", "a.xyz"); }),
              HasSubstr("needs at least 3 points, found 0"));
  EXPECT_THAT(input_error([] {
                parse_xyz("1 2 3\na 2 3\nnan 1 1\n2 2 2\n", "a.xyz",
                          {.skip_bad = true, .progress = {}});
              }),
              HasSubstr("needs at least 3 points, found 2 (2 bad records dropped)"));
  // Duplicates are points like any other.
  EXPECT_EQ(parse_xyz("1 2 3\n1 2 3\n1 2 3\n", "a.xyz").points.cols(), 3);
}

}  // namespace
}  // namespace polarform
