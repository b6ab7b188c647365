// Shared by the cam-job tests and the cam CLI tests: the bundled examples, self-removing scratch
// directories, whole files and directory snapshots, CSV tables, and each example's cam job computed
// and written once per test process.
#pragma once

#include <unistd.h>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "jobs/cam/cam_job.h"
#include "jobs/cam/cam_outputs.h"
#include "jobs/project/cam_project.h"

namespace polarform::cam_job_test {

namespace fs = std::filesystem;
using json = nlohmann::json;

inline const fs::path kExamples = fs::path(POLARFORM_SOURCE_DIR) / "examples" / "cams";
inline const std::vector<std::string> kExampleNames = {
    "roller",        "flat_faced",         "offset_roller",          "polynomial", "cylindrical",
    "scca_dynamics", "oscillating_roller", "oscillating_flat_faced", "grooved",    "conjugate"};

// A fresh directory under the system temporary directory (unique per process, since ctest runs
// tests in parallel processes), removed with its files on destruction.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : dir_(fs::temp_directory_path() /
             ("polarform_cam_job_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const fs::path& path() const { return dir_; }
  fs::path operator/(const std::string& file) const { return dir_ / file; }

 private:
  fs::path dir_;
};

// The alternatives of a cam job's result, for tests that know which cam they run.
inline const PlateProfile& plate_profile(const CamJobResult& r) {
  return std::get<PlateProfile>(r.conversion.profile);
}
inline const CylindricalTrack& track_of(const CamJobResult& r) {
  return std::get<CylindricalTrack>(r.conversion.profile);
}
inline const CamAnalysis& plate_analysis(const CamJobResult& r) {
  return std::get<PlateCamAnalysis>(r.analysis.cam).analysis;
}

inline std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void spit(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// Every file of a directory (hidden ones included) by name, with its content; empty if the
// directory does not exist.
inline std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& entry : fs::directory_iterator(dir))
    out[entry.path().filename().string()] = slurp(entry.path());
  return out;
}

inline json read_json(const fs::path& file) { return json::parse(slurp(file)); }

// A CSV file of numbers with one header line.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::size_t column(const std::string& name) const {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return k;
    throw std::runtime_error("no CSV column '" + name + "'");
  }
};

inline Csv read_csv(const fs::path& file) {
  Csv csv;
  std::istringstream in(slurp(file));
  std::string line;
  auto split = [](const std::string& text) {
    std::vector<std::string> fields;
    std::stringstream s(text);
    for (std::string field; std::getline(s, field, ',');) fields.push_back(field);
    return fields;
  };
  if (!std::getline(in, line)) throw std::runtime_error(file.string() + ": no header");
  csv.header = split(line);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (const std::string& field : split(line)) {
      double x = 0;
      const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), x);
      if (ec != std::errc() || ptr != field.data() + field.size())
        throw std::runtime_error(file.string() + ": not a number: '" + field + "'");
      row.push_back(x);
    }
    if (row.size() != csv.header.size()) throw std::runtime_error(file.string() + ": ragged row");
    csv.rows.push_back(std::move(row));
  }
  return csv;
}

inline CamProject load_example(const std::string& name) {
  std::vector<std::string> warnings;
  CamProject p = read_cam_project(kExamples / (name + ".xml"), warnings);
  if (!warnings.empty()) throw std::runtime_error(name + ": " + warnings.front());
  return p;
}

// One example's cam job, computed and written into its own scratch directory.
struct ExampleRun {
  // dir_name names the scratch directory (distinct runs of one example need distinct names).
  explicit ExampleRun(const std::string& name, const std::string& dir_name = "")
      : result(run_cam_job(load_example(name))), dir(dir_name.empty() ? name : dir_name) {
    CamOutputOptions options;
    options.design_name = name;
    files = write_cam_outputs(result, dir.path(), options);
  }
  CamJobResult result;
  ScratchDir dir;
  std::vector<std::string> files;
};

// The example's run, computed on first use and kept for the rest of the process.
inline const ExampleRun& example(const std::string& name) {
  static std::map<std::string, std::unique_ptr<ExampleRun>> runs;
  std::unique_ptr<ExampleRun>& run = runs[name];
  if (!run) run = std::make_unique<ExampleRun>(name);
  return *run;
}

}  // namespace polarform::cam_job_test
