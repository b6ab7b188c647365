// Bounded mutation fuzzing (tests/support/bounded_mutator.h) of the project readers: the cam,
// vessel, fit and pipe project files, seeded with the bundled examples and, for fit projects, with
// every attribute at once (pipe projects: the fuzz corpus's torus). Every mutant parses or throws
// InputError.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "jobs/project/cam_project.h"
#include "jobs/project/fit_project.h"
#include "jobs/project/pipe_project.h"
#include "jobs/project/vessel_project.h"
#include "tests/support/src/bounded_mutator.h"

namespace polarform {
namespace {

using fuzz_test::fuzz;
using fuzz_test::iterations;

std::string read_text(const std::string& relative) {
  std::ifstream in(std::string(POLARFORM_SOURCE_DIR) + "/" + relative, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ParserFuzz, CamProjectReaderAcceptsOrRejectsCleanly) {
  std::uint64_t rng_seed = 100;
  for (const char* example : {"examples/cams/roller.xml", "examples/cams/polynomial.xml",
                              "examples/cams/cylindrical.xml"}) {
    SCOPED_TRACE(example);
    fuzz(read_text(example),
         [](const std::string& text) {
           std::vector<std::string> warnings;
           parse_cam_project(text, "fuzz.xml", warnings);
         },
         rng_seed++, iterations());
  }
}

TEST(ParserFuzz, VesselProjectReaderAcceptsOrRejectsCleanly) {
  std::uint64_t rng_seed = 200;
  for (const char* example :
       {"examples/vessels/torispherical_100_6.xml", "examples/vessels/custom_curvature.xml"}) {
    SCOPED_TRACE(example);
    fuzz(read_text(example),
         [](const std::string& text) {
           std::vector<std::string> warnings;
           parse_vessel_project(text, "fuzz.xml", warnings);
         },
         rng_seed++, iterations());
  }
}

TEST(ParserFuzz, FitProjectReaderAcceptsOrRejectsCleanly) {
  const auto parse = [](const std::string& text) {
    std::vector<std::string> warnings;
    parse_fit_project(text, "fuzz.xml", warnings);
  };
  fuzz(read_text("examples/scans/sphere_like_fit.xml"), parse, 300, iterations());
  // Every attribute at once.
  fuzz("<polarform version=\"1\"><fit scan=\"a.ply\" method=\"cylindrical\" closed=\"no\" "
       "pole=\"cap\" degree=\"2,4\" tolerance=\"0.05\" tolerance-measure=\"p99\" "
       "center=\"1,2,3\" axis=\"0,0,1\" skip-bad=\"true\" fairness=\"fixed\" lambda=\"1e-4\" "
       "base=\"quartic\"/></polarform>",
       parse, 301, iterations());
}

TEST(ParserFuzz, PipeProjectReaderAcceptsOrRejectsCleanly) {
  fuzz(
      read_text("tests/fuzz/corpus/pipe_project/valid-circle-spine.xml"),
      [](const std::string& text) {
        std::vector<std::string> warnings;
        parse_pipe_project(text, "fuzz.xml", warnings);
      },
      400, iterations());
}

}  // namespace
}  // namespace polarform
