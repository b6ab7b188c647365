// libFuzzer harness of the patch boundary reader parse_boundary_csv (src/io/boundary_csv.h): a
// file is accepted with four curves of at least 2 finite points each, or refused.
#include <cstddef>
#include <cstdint>

#include "src/io/boundary_csv.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  using fuzz::require;
  fuzz::accepted([&] {
    const BoundaryPolylines b = parse_boundary_csv(fuzz::bytes_of(data, size), "fuzz.csv");
    for (const Eigen::Matrix3Xd& c : b.curves) {
      require(c.cols() >= 2, "a curve of fewer than 2 points was accepted");
      require(c.allFinite(), "a non-finite boundary coordinate");
    }
  });
  return 0;
}
