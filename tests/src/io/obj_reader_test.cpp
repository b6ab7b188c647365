// OBJ: only v lines count (with optional w or colour columns); faces, normals, texture
// coordinates, groups and comments are ignored; bad v lines are named by line.
#include "src/io/obj_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/src/sample_files.h"

namespace polarform {
namespace {

using io_test::input_error;
using ::testing::HasSubstr;

TEST(ObjReader, VertexLinesOnly) {
  const Eigen::Matrix3Xd expected = io_test::sample_points();
  const PointCloud cloud = parse_obj(io_test::sample_obj(expected), "part.obj");
  EXPECT_EQ(cloud.dropped, 0u);
  EXPECT_EQ(cloud.points, expected);
}

TEST(ObjReader, BadVertexLines) {
  const std::string head = "# part\nv 1 2 3\nvn 0 0 1\n";
  EXPECT_THAT(input_error([&] { parse_obj(head + "v 1 2 three\nv 1 1 1\n", "p.obj"); }),
              HasSubstr("p.obj: line 4: invalid number 'three'"));
  EXPECT_THAT(input_error([&] { parse_obj(head + "v 1 2\n", "p.obj"); }),
              HasSubstr("p.obj: line 4: expected 3 coordinates, found 2"));
  EXPECT_THAT(input_error([&] { parse_obj(head + "v 1 2 3\nv inf 1 1\n", "p.obj"); }),
              HasSubstr("p.obj: line 5: x is NaN or infinite"));
  const PointCloud cloud = parse_obj(head + "v 1 2 three\nv 4 5 6\nf 1 2 3\nv 7 8 9 # last\n",
                                     "p.obj", {.skip_bad = true, .progress = {}});
  EXPECT_EQ(cloud.dropped, 1u);
  ASSERT_EQ(cloud.points.cols(), 3);
  EXPECT_EQ(cloud.points.col(2), Eigen::Vector3d(7, 8, 9));
}

TEST(ObjReader, FacesWithoutEnoughVertices) {
  EXPECT_THAT(input_error([] { parse_obj("v 0 0 0\nv 1 0 0\nvt 0 0\nf 1 2 1\n", "p.obj"); }),
              HasSubstr("p.obj: needs at least 3 points, found 2"));
}

}  // namespace
}  // namespace polarform
