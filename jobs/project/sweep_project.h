// The sweep project file: a scan or mesh and how to recover its swept surface, as XML, so a sweep
// can be repeated and shared. Lengths in mm; the scan path is relative to the project file's
// folder (or absolute). Reading names file:line:attribute for every bad value and warns about
// unknown fields; writing is atomic, and a saved project loads back exactly.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "jobs/project/unknown_names.h"
#include "jobs/sweep/sweep_job.h"

namespace polarform {

struct SweepProject {
  std::filesystem::path scan;  // as written in the file
  SweepKind kind = SweepKind::automatic;
  std::optional<Eigen::Vector3d> axis, center;  // mm; center only with axis, not an extrusion
  std::optional<double> tolerance;              // mm; default 1e-4 of the size
  int degree = 3;
  double corner_angle_deg = 30.0;
  bool skip_bad = false;

  bool operator==(const SweepProject&) const = default;
};

// "auto", "revolution" or "extrusion".
const char* sweep_kind_word(SweepKind kind);

// The scan's path: `project.scan` taken relative to the folder of `project_file`.
std::filesystem::path scan_path(const SweepProject& project,
                                const std::filesystem::path& project_file);

// The job's options from the project (threads and interrogation stay the defaults).
SweepJobOptions sweep_job_options(const SweepProject& project);

// Reads <polarform version="1"><sweep …/></polarform>, or a bare <sweep> root:
//   <sweep scan="part.stl" kind="auto|revolution|extrusion|sections" axis="x,y,z" center="x,y,z"
//          tolerance="mm" degree="3" corner-angle="30" skip-bad="false"/>
// Throws InputError "file:line: <sweep> attribute 'x': expected …" for bad values, and for
// unknown attributes or elements, which UnknownNames::warn turns into warnings.
SweepProject read_sweep_project(const std::filesystem::path& file,
                                std::vector<std::string>& warnings,
                                UnknownNames policy = UnknownNames::refuse);
SweepProject parse_sweep_project(const std::string& text, const std::string& file,
                                 std::vector<std::string>& warnings,
                                 UnknownNames policy = UnknownNames::refuse);

// The project as XML (numbers in their shortest exact form) and saved atomically.
std::string sweep_project_xml(const SweepProject& project);
void write_sweep_project(const SweepProject& project, const std::filesystem::path& file);

}  // namespace polarform
