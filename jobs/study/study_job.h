// The study job behind `polarform study`: a tolerance sweep over a cam project's profile (quartic
// base, RQB base, cubic-through-points baseline, the compacted exact form and the degree-3 profile
// beside the peers' fits, Open CASCADE's and SISL's) and the angle-deviation relation of the base
// arcs, written as study.csv, study.svg, deviation.csv, deviation.svg and report.json.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "designers/convert/tolerance_study.h"
#include "jobs/project/cam_project.h"

namespace polarform {

struct StudyJobResult {
  std::vector<StudyRow> rows;
  std::vector<DeviationRow> deviation;
  bool peers =
      false;  // the rows carry the peer fits (asked for, and Open CASCADE or SISL available)
  double seconds = 0.0;
};

// Why a study has no peer columns, one line for the front ends.
std::string missing_peers_note(const StudyOptions& options);

StudyJobResult run_study_job(const CamProject& project, const std::vector<double>& tolerances,
                             const std::function<void(double)>& progress = {},
                             const StudyOptions& options = {});

// Writes the study files into dir (created if missing); returns their names.
std::vector<std::string> write_study_outputs(const StudyJobResult& r, const std::string& design_name,
                                             const std::filesystem::path& dir);

}  // namespace polarform
