// libFuzzer harness of the pipe spine reader parse_spine_csv (src/io/spine_csv.h): a file is
// accepted with at least 2 finite points, no point repeating the one before it, or refused.
#include <cstddef>
#include <cstdint>

#include "src/io/spine_csv.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  using fuzz::require;
  fuzz::accepted([&] {
    const Eigen::Matrix3Xd p = parse_spine_csv(fuzz::bytes_of(data, size), "fuzz.csv");
    require(p.cols() >= 2, "a spine of fewer than 2 points was accepted");
    require(p.allFinite(), "a non-finite spine coordinate");
    for (Eigen::Index k = 1; k < p.cols(); ++k)
      require(p.col(k) != p.col(k - 1), "a repeated spine point was accepted");
  });
  return 0;
}
