// PLY: ascii and both binary byte orders, float and double coordinates, other properties of every
// kind (lists included) and other elements before and after the vertices; hand-assembled files;
// and the specific errors for NaN, truncation, wrong counts and unsupported headers.
#include "src/io/ply_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <tuple>
#include <vector>

#include "src/io/ply_header.h"
#include "tests/support/src/sample_files.h"

namespace polarform {
namespace {

using io_test::input_error;
using io_test::PlyKind;
using ::testing::HasSubstr;

class PlyVariants : public ::testing::TestWithParam<std::tuple<PlyKind, bool, bool>> {};

TEST_P(PlyVariants, ReadsKnownCoordinates) {
  const auto [kind, doubles, vertex_list] = GetParam();
  const Eigen::Matrix3Xd expected = io_test::sample_points();
  const PointCloud cloud =
      parse_ply(io_test::sample_ply(expected, kind, doubles, vertex_list), "s.ply");
  EXPECT_EQ(cloud.dropped, 0u);
  ASSERT_EQ(cloud.points.cols(), 6);
  EXPECT_EQ(cloud.points, expected);
}

INSTANTIATE_TEST_SUITE_P(AllStoragesAndTypes, PlyVariants,
                         ::testing::Combine(::testing::Values(PlyKind::ascii,
                                                              PlyKind::binary_little_endian,
                                                              PlyKind::binary_big_endian),
                                            ::testing::Bool(), ::testing::Bool()));

TEST(PlyReader, DoubleCoordinatesKeepFullPrecision) {
  Eigen::Matrix3Xd points(3, 3);
  points << 0.1, 1.0 / 3.0, 1e-300, -2.0 / 7.0, 123456.789, 5e300, 0.7, -0.3, 2.5;
  for (const PlyKind kind :
       {PlyKind::ascii, PlyKind::binary_little_endian, PlyKind::binary_big_endian})
    EXPECT_EQ(parse_ply(io_test::sample_ply(points, kind, true), "d.ply").points, points);
}

// Bytes written out by hand: float 1.5 = 3F C0 00 00, -2 = C0 00 00 00, 0.25 = 3E 80 00 00.
TEST(PlyReader, HandAssembledBigAndLittleEndianFloats) {
  const std::string header_begin = "ply\nformat binary_big_endian 1.0\nelement vertex 3\n";
  const std::string header_end =
      "property float x\nproperty float y\nproperty float z\nend_header\n";
  std::string big = header_begin + header_end;
  std::string little =
      "ply\r\nformat binary_little_endian 1.0\r\nelement vertex 3\r\n"
      "property float x\r\nproperty float y\r\nproperty float z\r\nend_header\r\n";
  const unsigned char values[3][4] = {{0x3F, 0xC0, 0, 0}, {0xC0, 0, 0, 0}, {0x3E, 0x80, 0, 0}};
  for (int vertex = 0; vertex < 3; ++vertex)
    for (int k = 0; k < 3; ++k) {
      const auto* v = values[(vertex + k) % 3];
      big.append(reinterpret_cast<const char*>(v), 4);
      for (int b = 3; b >= 0; --b) little += static_cast<char>(v[b]);
    }
  Eigen::Matrix3Xd expected(3, 3);
  expected << 1.5, -2, 0.25, -2, 0.25, 1.5, 0.25, 1.5, -2;
  EXPECT_EQ(parse_ply(big, "big.ply").points, expected);
  EXPECT_EQ(parse_ply(little, "little.ply").points, expected);
}

TEST(PlyReader, HandWrittenAsciiMesh) {
  const std::string text =
      "ply\n"
      "format ascii 1.0\n"
      "comment a tetrahedron\n"
      "element vertex 4\n"
      "property double x\nproperty double y\nproperty double z\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element face 4\n"
      "property list uchar uint vertex_indices\n"
      "end_header\n"
      "0 0 0 255 0 0\n"
      "1.5 0 0 0 255 0\n"
      "0 -2.5 0 0 0 255\n"
      "0 0 1e3 9 9 9\n"
      "3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n";
  const PointCloud cloud = parse_ply(text, "t.ply");
  ASSERT_EQ(cloud.points.cols(), 4);
  EXPECT_EQ(cloud.points.col(1), Eigen::Vector3d(1.5, 0, 0));
  EXPECT_EQ(cloud.points.col(2), Eigen::Vector3d(0, -2.5, 0));
  EXPECT_EQ(cloud.points.col(3), Eigen::Vector3d(0, 0, 1000));
}

TEST(PlyReader, HeaderIsParsedInOrder) {
  const std::string file =
      io_test::sample_ply(io_test::sample_points(), PlyKind::binary_big_endian, false);
  const PlyHeader header = parse_ply_header(file, "s.ply");
  EXPECT_EQ(header.storage, PlyStorage::binary_big_endian);
  ASSERT_EQ(header.elements.size(), 4u);
  EXPECT_EQ(header.elements[1].name, "vertex");
  EXPECT_EQ(header.elements[1].count, 6u);
  ASSERT_EQ(header.elements[1].properties.size(), 7u);
  EXPECT_TRUE(header.elements[1].properties[4].is_list);
  EXPECT_EQ(header.elements[1].properties[4].count_type, PlyType::uint8);
  EXPECT_EQ(header.elements[1].properties[4].type, PlyType::int32);
  EXPECT_EQ(header.header_lines, 21u);
  EXPECT_EQ(file.substr(header.data_offset - 11, 11), "end_header\n");
}

// Binary little-endian float file with only x y z: vertex i starts at header + 12 i.
std::string plain_binary_ply(int declared, const std::vector<float>& values) {
  std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " +
                    std::to_string(declared) +
                    "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  for (const float v : values) io_test::put<float>(out, v, false);
  return out;
}

TEST(PlyReader, NanInBinaryNamesVertexAndByteOffset) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::string file = plain_binary_ply(4, {1, 2, 3, 4, 5, 6, 7, 8, nan, 1, 1, 1});
  const std::size_t header = file.size() - 48;
  EXPECT_THAT(input_error([&] { parse_ply(file, "n.ply"); }),
              HasSubstr("n.ply: vertex 2 (byte offset " + std::to_string(header + 24) +
                        "): z is NaN or infinite"));
  const PointCloud cloud = parse_ply(file, "n.ply", {.skip_bad = true, .progress = {}});
  EXPECT_EQ(cloud.dropped, 1u);
  ASSERT_EQ(cloud.points.cols(), 3);
  EXPECT_EQ(cloud.points.col(2), Eigen::Vector3d(1, 1, 1));
}

TEST(PlyReader, TruncatedBinaryAndWrongVertexCount) {
  std::vector<float> values(15, 1.0f);
  const std::string five = plain_binary_ply(5, values);
  EXPECT_EQ(parse_ply(five, "ok.ply").points.cols(), 5);
  const std::string truncated = five.substr(0, five.size() - 5);
  EXPECT_THAT(
      input_error([&] { parse_ply(truncated, "t.ply"); }),
      HasSubstr(
          "t.ply: vertex 4 (byte offset " + std::to_string(five.size() - 12) +
          "): the file is truncated inside this vertex (header declares 5 vertices of 12 bytes)"));
  EXPECT_THAT(
      input_error([&] { parse_ply(plain_binary_ply(9, values), "c.ply"); }),
      HasSubstr("c.ply: element 'vertex': header declares 9 vertices but the file holds only 5"));
  // With lists in the vertex the records are walked one by one.
  const std::string listed =
      io_test::sample_ply(io_test::sample_points(), PlyKind::binary_little_endian, false);
  // Material records take 13 + 5 bytes; vertex i takes 20 + 4 (i % 3) bytes.
  const std::size_t vertex_data = listed.find("end_header\n") + 11 + 13 + 5;
  EXPECT_THAT(input_error([&] { parse_ply(listed.substr(0, vertex_data + 54), "l.ply"); }),
              HasSubstr("l.ply: vertex 2 (byte offset " + std::to_string(vertex_data + 44) +
                        "): binary data ends inside this vertex"));
}

TEST(PlyReader, TruncationAfterTheVerticesIsReported) {
  const std::string file =
      io_test::sample_ply(io_test::sample_points(), PlyKind::binary_big_endian, true);
  // The edge element (8 bytes) is last, after the faces (13 + 17 bytes).
  EXPECT_THAT(input_error([&] { parse_ply(file.substr(0, file.size() - 3), "e.ply"); }),
              HasSubstr("e.ply: element 'edge': binary data ends before its 1 records"));
  EXPECT_THAT(
      input_error([&] { parse_ply(file.substr(0, file.size() - 8 - 17 + 3), "f.ply"); }),
      HasSubstr("f.ply: element 'face' record 1 (byte offset " +
                std::to_string(file.size() - 8 - 17) + "): binary data ends inside this record"));
  const std::string ascii = io_test::sample_ply(io_test::sample_points(), PlyKind::ascii, true);
  EXPECT_THAT(input_error([&] { parse_ply(ascii.substr(0, ascii.size() - 4), "a.ply"); }),
              HasSubstr("a.ply: line 31: file ends after 0 of the 1 records of element 'edge'"));
}

TEST(PlyReader, AsciiErrorsNameTheLine) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nproperty list uchar int n\nend_header\n";
  EXPECT_THAT(input_error([&] {
                parse_ply(header + "1 2 3 0\n1 2 3 0\n1 2 1.0abc 0\n1 2 3 0\n", "a.ply");
              }),
              HasSubstr("a.ply: line 11 (vertex 2): invalid number '1.0abc' for property 'z'"));
  EXPECT_THAT(input_error([&] { parse_ply(header + "1 2 3 0\n1 2 3 0\n1 2 3 0\n", "a.ply"); }),
              HasSubstr("a.ply: line 11: file ends after 3 of the 4 vertices"));
  EXPECT_THAT(
      input_error([&] { parse_ply(header + "1 2 3 0\n1 2 3 2 5\n1 2 3 0\n1 2 3 0\n", "a.ply"); }),
      HasSubstr("a.ply: line 10 (vertex 1): list 'n' declares 2 items but the line ends after 1"));
  EXPECT_THAT(input_error([&] { parse_ply(header + "1 2 3 0\n1 2\n1 2 3 0\n1 2 3 0\n", "a.ply"); }),
              HasSubstr("a.ply: line 10 (vertex 1): expected a value for property 'z'"));
  EXPECT_THAT(
      input_error([&] { parse_ply(header + "1 2 3 0 9\n1 2 3 0\n1 2 3 0\n1 2 3 0\n", "a.ply"); }),
      HasSubstr("a.ply: line 9 (vertex 0): more values than the 4 properties"));
  EXPECT_THAT(
      input_error([&] { parse_ply(header + "1 2 3 0\ninf 2 3 0\n1 2 3 0\n1 2 3 0\n", "a.ply"); }),
      HasSubstr("a.ply: line 10 (vertex 1): x is NaN or infinite"));
  std::string six = header;
  six.replace(six.find("vertex 4"), 8, "vertex 6");
  const PointCloud cloud = parse_ply(six + "1 2 3 0\n1 2 x 0\nnan 1 1 0\n4 5 6 1 7\n1 2\n0 0 0 0\n",
                                     "a.ply", {.skip_bad = true, .progress = {}});
  EXPECT_EQ(cloud.dropped, 3u);
  ASSERT_EQ(cloud.points.cols(), 3);
  EXPECT_EQ(cloud.points.col(1), Eigen::Vector3d(4, 5, 6));
}

TEST(PlyReader, HeaderErrors) {
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  EXPECT_THAT(
      input_error([&] {
        parse_ply("ply\nformat binary_middle_endian 1.0\nelement vertex 3\n" + xyz + "end_header\n",
                  "h.ply");
      }),
      HasSubstr("h.ply: line 2: unsupported PLY format 'binary_middle_endian'"));
  EXPECT_THAT(input_error([&] { parse_ply("plx\nformat ascii 1.0\n", "h.ply"); }),
              HasSubstr("h.ply: line 1: expected 'ply'"));
  EXPECT_THAT(
      input_error([&] { parse_ply("ply\nformat ascii 1.0\nelement vertex 3\n" + xyz, "h.ply"); }),
      HasSubstr("h.ply: PLY header has no 'end_header' line"));
  EXPECT_THAT(input_error([&] {
                parse_ply("ply\nformat ascii 1.0\nelement point 3\n" + xyz + "end_header\n",
                          "h.ply");
              }),
              HasSubstr("h.ply: PLY header: no 'vertex' element"));
  EXPECT_THAT(input_error([&] {
                parse_ply(
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float "
                    "y\nend_header\n",
                    "h.ply");
              }),
              HasSubstr("h.ply: PLY header: element 'vertex' has no property 'z'"));
  EXPECT_THAT(input_error([&] {
                parse_ply(
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty float "
                    "y\nproperty float z\nend_header\n",
                    "h.ply");
              }),
              HasSubstr("vertex property 'x' must be a float or double scalar"));
  EXPECT_THAT(input_error([&] {
                parse_ply("ply\nformat ascii 1.0\nelement vertex 3\nproperty float128 x\n",
                          "h.ply");
              }),
              HasSubstr("h.ply: line 4: unknown property type 'float128'"));
  EXPECT_THAT(
      input_error([&] { parse_ply("ply\nformat ascii 1.0\nelement vertex -3\n", "h.ply"); }),
      HasSubstr("h.ply: line 3: expected 'element <name> <count>'"));
  EXPECT_THAT(input_error([&] {
                parse_ply("ply\nformat ascii 1.0\nelement face 1\nproperty list float int v\n",
                          "h.ply");
              }),
              HasSubstr("h.ply: line 4: list count type 'float'"));
  EXPECT_THAT(
      input_error([&] { parse_ply("ply\nelement vertex 3\n" + xyz + "end_header\n", "h.ply"); }),
      HasSubstr("h.ply: line 6: PLY header has no 'format' line"));
  EXPECT_THAT(input_error([&] { parse_ply("ply\nformat ascii 1.0\nelemnt vertex 3\n", "h.ply"); }),
              HasSubstr("h.ply: line 3: unknown PLY header keyword 'elemnt'"));
}

TEST(PlyReader, HugeDeclaredCountIsAnErrorNotAnAllocation) {
  EXPECT_THAT(input_error([] {
                parse_ply(plain_binary_ply(2000000000, {1, 2, 3}), "big.ply");
              }),
              HasSubstr("header declares 2000000000 vertices but the file holds only 1"));
  const std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 18446744073709551615\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n1 2 3\n";
  EXPECT_THAT(input_error([&] { parse_ply(ascii, "big.ply"); }),
              HasSubstr("file ends after 1 of the 18446744073709551615 vertices"));
}

TEST(PlyReader, FewerThanThreeVertices) {
  EXPECT_THAT(input_error([] {
                parse_ply(plain_binary_ply(2, {1, 2, 3, 4, 5, 6}), "two.ply");
              }),
              HasSubstr("two.ply: needs at least 3 points, found 2"));
}

}  // namespace
}  // namespace polarform
