// Shared helpers of the vessel job and CLI tests: the bundled example projects, project text
// written to a scratch file, fresh scratch directories and what a directory holds.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "jobs/project/vessel_project.h"

namespace polarform::vessel_job_test {

inline std::filesystem::path example(const std::string& name) {
  return std::filesystem::path(POLARFORM_SOURCE_DIR) / "examples" / "vessels" / name;
}

inline const std::vector<std::string>& example_names() {
  static const std::vector<std::string> names = {
      "hemispherical.xml",    "ellipsoidal_2_1.xml",           "torispherical_100_6.xml",
      "custom_curvature.xml", "torispherical_100_6_exact.xml", "minimum_stress_2_1_depth.xml"};
  return names;
}

inline VesselProject load_example(const std::string& name) {
  std::vector<std::string> warnings;
  VesselProject p = read_vessel_project(example(name), warnings);
  EXPECT_TRUE(warnings.empty()) << name;
  return p;
}

// An empty directory of its own for the running test.
inline std::filesystem::path scratch_dir(const std::string& tag) {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  // Named by the build too, so that two builds' runs of the same test never share it.
  const std::size_t build = std::hash<std::string>{}(POLARFORM_BINARY_DIR);
  const std::string name = "polarform_vessel_job_" + std::string(info->name()) + "_" + tag + "_" +
                           std::to_string(build % 1000000007);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::filesystem::path write_text(const std::filesystem::path& file,
                                        const std::string& text) {
  std::ofstream(file) << text;
  return file;
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::set<std::string> files_in(const std::filesystem::path& dir) {
  std::set<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    out.insert(e.path().filename().string());
  return out;
}

// A vessel project (R 500 mm, L 1500 mm, t 10 mm, p 2 MPa) with children from line 3.
inline std::string vessel_xml(const std::string& children,
                              const std::string& synthesis = "<synthesis/>") {
  return "<?xml version=\"1.0\"?>\n<polarform version=\"1\"><vessel radius=\"500\" length=\"1500\" "
         "thickness=\"10\" pressure=\"2\">\n" + children + "\n" + synthesis +
         "\n</vessel></polarform>\n";
}

// Symmetry about θ = 90° forces R(π) = R(0), so R(π) = 480 contradicts R(0) = 500.
inline std::string contradictory_project() {
  return vessel_xml(
      "<head preset=\"hemispherical\"/>\n<end at=\"A\" r=\"500\"/>\n<end at=\"B\" r=\"480\"/>",
      "<synthesis symmetric=\"true\"/>");
}

// Two targets with free end radii, allowed two evaluations: SLSQP cannot converge.
inline std::string non_converging_project() {
  return vessel_xml(
      "<curvature theta=\"30\" radius=\"400\"/>\n<curvature theta=\"90\" radius=\"300\"/>\n"
      "<end at=\"A\" dr=\"0\" ddr=\"0\"/>\n<end at=\"B\" dr=\"0\" ddr=\"0\"/>",
      "<synthesis max-iterations=\"2\"/>");
}

}  // namespace polarform::vessel_job_test
