// `polarform study` on examples/cams/roller.xml over 1e-2:1e-4 mm (--no-peers) writes the same
// tables and plots, byte for byte, as the study job run in process; at 1e-2 mm its stdout table has
// the peer columns and ratios, or with --no-peers a note instead.
#include <gtest/gtest.h>

#include <regex>

#include "designers/convert/occt_peer.h"
#include "designers/convert/sisl_peer.h"
#include "tests/support/jobs/cam_job_support.h"
#include "tests/support/jobs/study_run.h"
#include "tests/ui/cli/cli_run.h"

namespace polarform {
namespace {

using namespace cam_job_test;

TEST(StudyCli, WritesTheSameTablesAsTheJob) {
  const ScratchDir scratch("study_cli");
  const CliRun run = run_cli({"study", (kExamples / "roller.xml").string(), "--out",
                              (scratch / "out").string(), "--tol", "1e-2:1e-4", "--no-peers", "-q"},
                             scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  for (const char* table : {"study.csv", "deviation.csv", "study.svg", "deviation.svg"})
    EXPECT_TRUE(slurp(scratch / "out" / table) == slurp(study().dir / table)) << table;
}

TEST(StudyCli, PrintsThePeerColumnsOrANote) {
  const ScratchDir scratch("study_cli_peers");
  const auto study = [&](bool peers) {
    std::vector<std::string> args = {"study", (kExamples / "roller.xml").string(),
                                     "--out", (scratch / "out").string(),
                                     "--tol", "1e-2:1e-2"};
    if (!peers) args.push_back("--no-peers");
    return run_cli(args, scratch);
  };
  const CliRun with = study(true), without = study(false);
  ASSERT_EQ(with.status, 0) << with.err;
  ASSERT_EQ(without.status, 0) << without.err;
  EXPECT_NE(without.out.find("peers: not asked for (--no-peers), no peer columns"),
            std::string::npos)
      << without.out;
  EXPECT_EQ(without.out.find("occt 3"), std::string::npos) << without.out;
  if (!kOcctPeersAvailable && !kSislPeersAvailable) {
    EXPECT_NE(with.out.find("peers: neither Open CASCADE nor SISL is available"),
              std::string::npos);
    return;
  }
  if (!kOcctPeersAvailable || !kSislPeersAvailable) return;  // the counts below need both
  // The roller at 1e-2 mm: exact form 16 (the product's 4 arcs, refitted), degree 3 17, OCCT
  // degree 3 31 and degrees 3..8 27, SISL degree 3 32 and best of 3..8 26 control points (as
  // tests/jobs/study/peer_counts_test.cpp records), ratios 16/26 and 17/26.
  for (const char* text : {"exact arcs/ctrl", "deg 3", "occt 3", "occt 3..8", "sisl 3", "sisl 3..8",
                           "exact/best", "deg 3/best"})
    EXPECT_NE(with.out.find(text), std::string::npos) << text << "\n" << with.out;
  EXPECT_TRUE(
      std::regex_search(with.out, std::regex(" 4/16 +17 +31 +27 +32 +26 +0\\.62 +0\\.65\\b")))
      << with.out;
  EXPECT_EQ(with.out.find("peers:"), std::string::npos) << with.out;
}

}  // namespace
}  // namespace polarform
