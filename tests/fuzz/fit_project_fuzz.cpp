// libFuzzer harness of the fit project reader parse_fit_project (jobs/project/fit_project.h).
// A project it accepts must survive the writer: fit_project_xml of it parses again and writes the
// same text (the writer and the reader agree on every value they let through).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "jobs/project/fit_project.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  const std::string text(fuzz::bytes_of(data, size));
  std::vector<std::string> warnings;
  std::string written;
  if (!fuzz::accepted(
          [&] { written = fit_project_xml(parse_fit_project(text, "fuzz.xml", warnings)); }))
    return 0;
  std::string rewritten;
  if (!fuzz::accepted(
          [&] { rewritten = fit_project_xml(parse_fit_project(written, "fuzz.xml", warnings)); }))
    fuzz::finding("the reader refuses what the writer wrote of an accepted project");
  fuzz::require(rewritten == written, "writing a re-read project changes it");
  return 0;
}
