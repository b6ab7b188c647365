// libFuzzer harness of the OFF (Geomview), with or without colours reader parse_off
// (src/io/off_reader.h).
#include <cstddef>
#include <cstdint>

#include "src/io/off_reader.h"
#include "tests/fuzz/cloud_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  fuzz::check_cloud_reader(fuzz::bytes_of(data, size),
                           [](std::string_view bytes, const ReadOptions& options) {
                             return parse_off(bytes, "fuzz.off", options);
                           });
  return 0;
}
