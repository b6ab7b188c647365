// What every project harness requires: the reader accepts the text or refuses it with an
// InputError, and a project it accepts survives its writer — written, read again and written
// to the same text (the writer and the reader agree on every value they let through).
#pragma once

#include <string>
#include <vector>

#include "tests/fuzz/fuzz_check.h"

namespace polarform::fuzz {

// parse(text, file, warnings) -> Project and write(Project) -> XML text, e.g. parse_cam_project
// and cam_project_xml.
template <class Parse, class Write>
void check_project_reader(const std::string& text, Parse&& parse, Write&& write) {
  std::vector<std::string> warnings;
  std::string written;
  if (!accepted([&] { written = write(parse(text, "fuzz.xml", warnings)); })) return;
  std::string rewritten;
  if (!accepted([&] { rewritten = write(parse(written, "fuzz.xml", warnings)); }))
    finding("the reader refuses what the writer wrote of an accepted project");
  require(rewritten == written, "writing a re-read project changes it");
}

}  // namespace polarform::fuzz
