// The boundary file of `polarform patch --boundary`: comma-separated text under the header
// `curve,x,y,z`; every row is a point of one of four polylines, curve 0 to 3 in loop order, each
// curve's rows together and in order (a curve may run either way; the patch designer orients
// them). '#' starts a comment, blank lines are skipped. Every error names the file, the line and
// the field; the parser reads only the bytes it is given (fuzzed: tests/fuzz/boundary_fuzz.cpp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <string>
#include <string_view>

namespace polarform {

struct BoundaryPolylines {
  std::array<Eigen::Matrix3Xd, 4> curves;  // the points of curve k, in file order
};

// Throws InputError "name:line: …" for a missing or wrong header, a wrong field count, a bad or
// non-finite number, a curve index outside 0..3, curves out of order or split, or a curve with
// fewer than 2 points.
BoundaryPolylines parse_boundary_csv(std::string_view text, const std::string& name);
BoundaryPolylines read_boundary_csv(const std::filesystem::path& file);

}  // namespace polarform
