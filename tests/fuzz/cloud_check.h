// The invariants of a point cloud read from fuzzed bytes (src/io/point_cloud.h): at least three
// points, every coordinate finite, and a progress callback called with increasing fractions in
// (0, 1], at most 100 times.
#pragma once

#include <functional>
#include <string_view>

#include "src/io/point_cloud.h"
#include "tests/fuzz/fuzz_check.h"

namespace polarform::fuzz {

// Parses `bytes` with `parse(bytes, options)` twice, strict and with skip_bad, checking every
// invariant of the result and of the progress calls.
template <class Parse>
void check_cloud_reader(std::string_view bytes, Parse&& parse) {
  for (const bool skip_bad : {false, true}) {
    int calls = 0;
    double last = 0.0;
    ReadOptions options;
    options.skip_bad = skip_bad;
    options.progress = [&](double fraction) {
      require(fraction > last && fraction <= 1.0, "progress fraction not increasing in (0, 1]");
      last = fraction;
      require(++calls <= 100, "progress called more than 100 times");
    };
    accepted([&] {
      const PointCloud cloud = parse(bytes, options);
      require(cloud.points.cols() >= 3, "a cloud of fewer than 3 points was accepted");
      require(cloud.points.allFinite(), "a non-finite coordinate was accepted");
      require(skip_bad || cloud.dropped == 0, "records dropped without skip_bad");
    });
  }
}

}  // namespace polarform::fuzz
