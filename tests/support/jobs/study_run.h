// The study job on examples/cams/roller.xml over 1e-2:1e-4 mm (two steps per decade) without the
// peer fits (tests/jobs/study/study_peers_test.cpp has them), computed and written once per test
// process: what the study-job tests check and what `polarform study --no-peers` must reproduce.
#pragma once

#include <string>
#include <vector>

#include "jobs/study/study_job.h"
#include "tests/support/jobs/cam_job_support.h"

namespace polarform::cam_job_test {

struct StudyRun {
  StudyRun() : dir("study") {
    result = run_study_job(load_example("roller"), log_tolerances(1e-2, 1e-4, 2), {},
                           StudyOptions{.peers = false});
    files = write_study_outputs(result, "roller", dir.path());
  }
  StudyJobResult result;
  ScratchDir dir;
  std::vector<std::string> files;
};

inline const StudyRun& study() {
  static const StudyRun run;
  return run;
}

}  // namespace polarform::cam_job_test
