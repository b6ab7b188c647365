// The patch boundary reader: four polylines under `curve,x,y,z`, every refusal naming the line and
// the field.
#include "src/io/boundary_csv.h"

#include <gtest/gtest.h>

#include <string>

#include "src/error.h"

namespace polarform {
namespace {

const std::string kSquare =
    "# a boundary\ncurve,x,y,z\n0,0,0,0\n0,1,0,0\n1,1,0,0\n1, 1, 1, 0.5\n\n"
    "2,1,1,0.5\n2,0,1,0  # back\n3,0,1,0\n3,0,0,0\n";

std::string refusal(const std::string& text) {
  try {
    parse_boundary_csv(text, "b.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(BoundaryCsv, ReadsFourCurvesInFileOrder) {
  const BoundaryPolylines b = parse_boundary_csv(kSquare, "b.csv");
  for (const Eigen::Matrix3Xd& c : b.curves) EXPECT_EQ(c.cols(), 2);
  EXPECT_EQ(b.curves[1].col(1), Eigen::Vector3d(1, 1, 0.5));
  EXPECT_EQ(b.curves[2].col(1), Eigen::Vector3d(0, 1, 0));
}

TEST(BoundaryCsv, RefusalsNameTheLineAndTheField) {
  EXPECT_EQ(refusal(""), "b.csv: no header line; expected 'curve,x,y,z'");
  EXPECT_EQ(refusal("curve,x,y\n"), "b.csv:1: header 'curve,x,y': expected 'curve,x,y,z'");
  EXPECT_EQ(refusal("curve,x,y,z\n0,1,2\n"), "b.csv:2: expected 4 fields (curve,x,y,z), found 3");
  EXPECT_EQ(refusal("curve,x,y,z\n4,1,2,3\n"), "b.csv:2: curve '4': expected 0, 1, 2 or 3");
  EXPECT_EQ(refusal("curve,x,y,z\n0.5,1,2,3\n"), "b.csv:2: curve '0.5': expected 0, 1, 2 or 3");
  EXPECT_EQ(refusal("curve,x,y,z\n0,1,nan,3\n"), "b.csv:2: y 'nan': expected a finite number");
  EXPECT_EQ(refusal("curve,x,y,z\n1,1,2,3\n0,1,2,3\n"),
            "b.csv:3: curve 0 after curve 1: the rows of each curve must be together, curves 0 to "
            "3 in loop order");
  EXPECT_EQ(refusal(kSquare + "0,2,2,2\n"),
            "b.csv:12: curve 0 after curve 3: the rows of each curve must be together, curves 0 to "
            "3 in loop order");
  EXPECT_EQ(refusal("curve,x,y,z\n0,0,0,0\n0,1,0,0\n1,1,0,0\n1,1,1,0\n3,0,1,0\n3,0,0,0\n"),
            "b.csv: curve 2 has 0 point(s); a boundary needs four curves of at least 2 points "
            "each");
}

TEST(BoundaryCsv, MissingFileIsNamed) {
  EXPECT_THROW(read_boundary_csv("/nonexistent/b.csv"), InputError);
}

}  // namespace
}  // namespace polarform
