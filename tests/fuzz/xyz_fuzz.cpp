// libFuzzer harness of the delimited text: xyz, csv, txt reader parse_xyz (src/io/xyz_reader.h).
#include <cstddef>
#include <cstdint>

#include "src/io/xyz_reader.h"
#include "tests/fuzz/cloud_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  fuzz::check_cloud_reader(fuzz::bytes_of(data, size),
                           [](std::string_view bytes, const ReadOptions& options) {
                             return parse_xyz(bytes, "fuzz.xyz", options);
                           });
  return 0;
}
