// Helpers of the job and CLI tests: a fresh scratch directory per test, small files written into
// it, the names of the files a directory holds, and the report.json a job wrote.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace polarform::test {

namespace fs = std::filesystem;

// An empty directory named after the running test, under the system's temporary directory.
inline fs::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  // Named by the build too: two builds' test runs (two checkouts, CI beside a developer) may run
  // the same test at the same time; one build's next run reuses (and first empties) its own.
  const std::size_t build = std::hash<std::string>{}(POLARFORM_BINARY_DIR);
  const fs::path dir =
      fs::temp_directory_path() / ("polarform_" + std::string(info->test_suite_name()) + "_" +
                                   info->name() + "_" + std::to_string(build % 1000000007));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline fs::path write_text(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

inline std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

inline nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

inline std::string example(const std::string& relative) {
  return std::string(POLARFORM_SOURCE_DIR) + "/examples/" + relative;
}

}  // namespace polarform::test
