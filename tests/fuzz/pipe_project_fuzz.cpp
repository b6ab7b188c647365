// libFuzzer harness of the pipe project reader parse_pipe_project (jobs/project/pipe_project.h),
// with the writer round trip of tests/fuzz/project_check.h.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "jobs/project/pipe_project.h"
#include "tests/fuzz/project_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  fuzz::check_project_reader(
      std::string(fuzz::bytes_of(data, size)),
      [](const std::string& text, const std::string& file, std::vector<std::string>& warnings) {
        return parse_pipe_project(text, file, warnings);
      },
      [](const auto& project) { return pipe_project_xml(project); });
  return 0;
}
