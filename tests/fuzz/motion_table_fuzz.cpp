// libFuzzer harness of the motion table reader parse_motion_table (jobs/project/motion_table_csv.h)
// and its interpolation: any bytes give a table whose spline runs from S(0) = 0 to S(1) = 1, or
// the documented InputError.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "designers/cam/motion_table.h"
#include "jobs/project/motion_table_csv.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace polarform;
  const TableSegment segment{std::numbers::pi / 2, std::numbers::pi, 20, size % 2 == 0};
  const TableEnds ends = size % 3 == 0 ? TableEnds::Free : TableEnds::Rest;
  fuzz::accepted([&] {
    const BSplineFunction f = interpolate_motion_table(
        parse_motion_table(fuzz::bytes_of(data, size), "fuzz.csv", segment, ends));
    fuzz::require(std::abs(f(0.0)) <= 1e-9 && std::abs(f(1.0) - 1) <= 1e-9,
                  "table spline misses S(0) = 0 or S(1) = 1");
  });
  return 0;
}
