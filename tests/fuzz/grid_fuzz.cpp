// libFuzzer harness of the viz grid reader parse_scalar_grid (src/io/grid_reader.h): a grid is
// accepted with at least 16 rows of equal length, finite numbers and φ in [0, π], or refused.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "src/io/grid_reader.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  using fuzz::require;
  fuzz::accepted([&] {
    const ScalarGrid grid = parse_scalar_grid(fuzz::bytes_of(data, size), "fuzz.csv");
    const auto rows = grid.value.size();
    require(rows >= 16, "a grid of fewer than 16 rows was accepted");
    require(grid.value.allFinite() && grid.theta.allFinite(), "a non-finite grid value");
    require(grid.theta.size() == rows, "theta and value differ in length");
    if (grid.setup == GridSetup::spherical) {
      require(grid.phi.size() == rows, "phi and value differ in length");
      require(grid.phi.allFinite() && grid.phi.minCoeff() >= 0.0 &&
                  grid.phi.maxCoeff() <= std::numbers::pi,
              "phi outside [0, pi]");
    } else {
      require(grid.z.size() == rows && grid.z.allFinite(), "z missing or not finite");
    }
  });
  return 0;
}
