// The spine file of `polarform pipe`: comma-separated text under the header `x,y,z`, one point of
// the spine per row, in order along it. '#' starts a comment, blank lines are skipped. Every error
// names the file, the line and the field; the parser reads only the bytes it is given (fuzzed:
// tests/fuzz/spine_fuzz.cpp).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <string_view>

namespace polarform {

// Throws InputError "name:line: …" for a missing or wrong header, a wrong field count, a bad or
// non-finite number, fewer than 2 points, or two consecutive points that coincide.
Eigen::Matrix3Xd parse_spine_csv(std::string_view text, const std::string& name);
Eigen::Matrix3Xd read_spine_csv(const std::filesystem::path& file);

}  // namespace polarform
