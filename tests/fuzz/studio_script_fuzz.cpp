// libFuzzer harness of the studio's --script parser parse_script (ui/studio/studio_script.h):
// every accepted action has a line number within the script.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "tests/fuzz/fuzz_check.h"
#include "ui/studio/studio_script.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  const std::string text(fuzz::bytes_of(data, size));
  fuzz::accepted([&] {
    std::istringstream in(text);
    for (const studio::ScriptAction& action : studio::parse_script(in, "/fuzz/script.txt"))
      fuzz::require(action.line >= 1 && static_cast<std::size_t>(action.line) <= size + 1,
                    "an action with a line number outside the script");
  });
  return 0;
}
