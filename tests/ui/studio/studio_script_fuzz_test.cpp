// Bounded mutation fuzzing (tests/support/bounded_mutator.h) of the studio's --script parser,
// seeded with a session script. Every mutant parses or throws InputError.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "tests/support/src/bounded_mutator.h"
#include "ui/studio/studio_script.h"

namespace polarform {
namespace {

using fuzz_test::fuzz;
using fuzz_test::iterations;

TEST(ParserFuzz, StudioScriptParserAcceptsOrRejectsCleanly) {
  const std::string seed =
      "# a session\nopen cams/roller.xml\ndrop a.xyz \"b c.ply\"\ntemplate vessel hemispherical\n"
      "workspace fit\nedit\nundo\nredo\nsave\nsave-as \"out/my cam.xml\"\n"
      "export all out\nscreenshot shot.png\nnumbers after\n";
  fuzz(seed,
       [](const std::string& text) {
         std::istringstream in(text);
         studio::parse_script(in, "/fuzz/script.txt");
       },
       400, iterations());
}

}  // namespace
}  // namespace polarform
