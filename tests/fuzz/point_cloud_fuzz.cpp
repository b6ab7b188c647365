// libFuzzer harness of the point-cloud entry point parse_point_cloud (src/io/point_cloud.h): the
// first byte picks the file name's extension, so format detection by signature, extension and
// sniffing is fuzzed together with every reader.
#include <array>
#include <cstddef>
#include <cstdint>

#include "src/io/point_cloud.h"
#include "tests/fuzz/cloud_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  if (size == 0) return 0;
  static constexpr std::array<const char*, 8> kNames = {
      "scan.xyz", "scan.csv", "scan.txt", "scan.ply", "scan.stl", "scan.obj", "scan.off", "scan"};
  const char* name = kNames[data[0] % kNames.size()];
  fuzz::check_cloud_reader(fuzz::bytes_of(data + 1, size - 1),
                           [name](std::string_view bytes, const ReadOptions& options) {
                             return parse_point_cloud(bytes, name, options);
                           });
  return 0;
}
