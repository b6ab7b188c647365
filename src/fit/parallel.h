// Splitting a loop over n items into contiguous chunks run on a few threads (the caller's thread
// runs the first chunk). Fits assemble, synchronise and measure millions of points this way;
// results are independent of the thread count up to the order of floating-point summation.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <utility>

namespace polarform {

// Progress report: the fraction done in [0, 1], increasing.
using ProgressFn = std::function<void(double)>;

// Threads worth using for n items: 1 below `min_chunk` items per thread, else min(requested, n).
int worker_count(int requested, std::size_t n, std::size_t min_chunk = 20000);

// Calls body(begin, end, chunk) for `chunks` contiguous ranges covering [0, n), concurrently.
// An exception thrown by any chunk is rethrown on the caller's thread after all have finished.
void parallel_chunks(std::size_t n, int chunks,
                     const std::function<void(std::size_t, std::size_t, int)>& body);

// Maps a stage's own progress in [0, 1] to [from, to] of an overall callback (may be empty);
// reports that would go backwards (also across its sub-ranges) are dropped. Call from one thread.
class ProgressRange {
 public:
  ProgressRange() = default;
  ProgressRange(ProgressFn sink, double from, double to)
      : sink_(std::move(sink)), from_(from), to_(to), last_(std::make_shared<double>(from)) {}
  void operator()(double fraction);
  // The sub-range [a, b] (fractions of this range) as a range of the same callback.
  ProgressRange sub(double a, double b) const;

 private:
  ProgressFn sink_;
  double from_ = 0.0, to_ = 1.0;
  std::shared_ptr<double> last_ = std::make_shared<double>(0.0);
};

}  // namespace polarform
