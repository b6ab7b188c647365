// STL: ascii and binary against known coordinates, a binary file whose header starts with
// "solid", and the errors for truncation, NaN and unknown keywords.
#include "src/io/stl_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "tests/support/src/sample_files.h"

namespace polarform {
namespace {

using io_test::input_error;
using ::testing::HasSubstr;

TEST(StlReader, BinaryGivesEveryTriangleVertex) {
  const Eigen::Matrix3Xd expected = io_test::sample_points();
  const std::string file = io_test::binary_stl(expected, "exported by a CAD system");
  EXPECT_EQ(file.size(), 84u + 2 * 50u);
  EXPECT_TRUE(has_binary_stl_size(file));
  const PointCloud cloud = parse_stl(file, "part.stl");
  EXPECT_EQ(cloud.points, expected);
}

TEST(StlReader, BinaryWhoseHeaderStartsWithSolid) {
  const Eigen::Matrix3Xd expected = io_test::sample_points();
  const std::string file = io_test::binary_stl(expected, "solid part, binary but says solid");
  EXPECT_EQ(parse_stl(file, "part.stl").points, expected);
}

TEST(StlReader, Ascii) {
  const Eigen::Matrix3Xd expected = io_test::sample_points();
  const std::string file = io_test::ascii_stl(expected);
  EXPECT_FALSE(has_binary_stl_size(file));
  EXPECT_EQ(parse_stl(file, "part.stl").points, expected);
  const std::string crlf_two_solids =
      "solid a\r\nfacet normal 0 0 1\r\nouter loop\r\nvertex 1 2 3\r\nvertex 4 5 6\r\n"
      "vertex 7 8 9\r\nendloop\r\nendfacet\r\nendsolid a\r\nsolid b\r\nfacet normal 0 0 1\r\n"
      "outer loop\r\nvertex -1 -2 -3\r\nvertex 0 0 0\r\nvertex 1e1 2e1 3e1\r\nendloop\r\n"
      "endfacet\r\nendsolid b\r\n";
  const PointCloud cloud = parse_stl(crlf_two_solids, "two.stl");
  ASSERT_EQ(cloud.points.cols(), 6);
  EXPECT_EQ(cloud.points.col(3), Eigen::Vector3d(-1, -2, -3));
  EXPECT_EQ(cloud.points.col(5), Eigen::Vector3d(10, 20, 30));
}

TEST(StlReader, TruncatedBinaryEvenWithSolidHeader) {
  const std::string file = io_test::binary_stl(io_test::sample_points(), "solid trap");
  EXPECT_THAT(
      input_error([&] { parse_stl(file.substr(0, file.size() - 7), "t.stl"); }),
      HasSubstr("t.stl: triangle 1 (byte offset 134): the file is truncated inside this "
                "triangle: binary STL header declares 2 triangles (184 bytes), the file has 177"));
  EXPECT_THAT(input_error([&] { parse_stl(file.substr(0, 134), "t.stl"); }),
              HasSubstr("t.stl: triangle 1 (byte offset 134): the file ends before this triangle"));
  EXPECT_THAT(
      input_error([&] { parse_stl(file + "junk", "t.stl"); }),
      HasSubstr("declares 2 triangles (184 bytes), the file has 188: wrong triangle count"));
  EXPECT_THAT(input_error([] { parse_stl("not an stl", "t.stl"); }),
              HasSubstr("t.stl: not an STL file"));
}

TEST(StlReader, NanInBinaryNamesTriangleVertexAndOffset) {
  Eigen::Matrix3Xd points = io_test::sample_points();
  points(1, 5) = std::numeric_limits<double>::infinity();
  const std::string file = io_test::binary_stl(points, "");
  EXPECT_THAT(input_error([&] { parse_stl(file, "n.stl"); }),
              HasSubstr("n.stl: triangle 1 vertex 2 (byte offset 170): y is NaN or infinite"));
  const PointCloud cloud = parse_stl(file, "n.stl", {.skip_bad = true, .progress = {}});
  EXPECT_EQ(cloud.dropped, 1u);
  EXPECT_EQ(cloud.points.cols(), 5);
}

TEST(StlReader, AsciiErrorsNameTheLine) {
  const std::string head = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 1 2 3\n";
  EXPECT_THAT(input_error([&] { parse_stl(head + "vertex 1 2 x\nvertex 1 2 3\n", "a.stl"); }),
              HasSubstr("a.stl: line 5: invalid number 'x'"));
  EXPECT_THAT(input_error([&] { parse_stl(head + "vertex 1 2\nvertex 1 2 3\n", "a.stl"); }),
              HasSubstr("a.stl: line 5: expected 3 coordinates, found 2"));
  EXPECT_THAT(input_error([&] { parse_stl(head + "vertx 1 2 3\n", "a.stl"); }),
              HasSubstr("a.stl: line 5: unknown ASCII STL keyword 'vertx'"));
  const PointCloud cloud = parse_stl(head + "vertex 1 2 x\nvertex 4 5 6\nvertex 7 8 9\n", "a.stl",
                                     {.skip_bad = true, .progress = {}});
  EXPECT_EQ(cloud.dropped, 1u);
  EXPECT_EQ(cloud.points.col(2), Eigen::Vector3d(7, 8, 9));
}

}  // namespace
}  // namespace polarform
