// libFuzzer harness of the STL, ascii and binary reader parse_stl (src/io/stl_reader.h).
#include <cstddef>
#include <cstdint>

#include "src/io/stl_reader.h"
#include "tests/fuzz/cloud_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  fuzz::check_cloud_reader(fuzz::bytes_of(data, size),
                           [](std::string_view bytes, const ReadOptions& options) {
                             return parse_stl(bytes, "fuzz.stl", options);
                           });
  return 0;
}
