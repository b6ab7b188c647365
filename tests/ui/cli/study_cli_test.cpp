// `polarform study` on examples/cams/roller.xml over 1e-2:1e-4 mm writes the same tables and plots,
// byte for byte, as the study job run in process.
#include <gtest/gtest.h>

#include "tests/support/jobs/cam_job_support.h"
#include "tests/support/jobs/study_run.h"
#include "tests/ui/cli/cli_run.h"

namespace polarform {
namespace {

using namespace cam_job_test;

TEST(StudyCli, WritesTheSameTablesAsTheJob) {
  const ScratchDir scratch("study_cli");
  const CliRun run = run_cli({"study", (kExamples / "roller.xml").string(), "--out",
                              (scratch / "out").string(), "--tol", "1e-2:1e-4", "-q"},
                             scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  for (const char* table : {"study.csv", "deviation.csv", "study.svg", "deviation.svg"})
    EXPECT_TRUE(slurp(scratch / "out" / table) == slurp(study().dir / table)) << table;
}

}  // namespace
}  // namespace polarform
