// Costly independent items (R's evaluations at a table's nodes, a curve's error over each arc)
// shared by the calling thread and one helper on the 2-core machine.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <future>

namespace polarform {

// f(i) for i = 0..count − 1, the items taken `chunk` at a time from a shared counter by the caller
// and one helper thread, so that the two finish together whatever each item costs; the caller
// alone when count <= chunk. f must be safe to call concurrently for different i; an exception
// from either thread reaches the caller.
template <class F>
void on_two_threads(std::size_t count, std::size_t chunk, const F& f) {
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t c; (c = next.fetch_add(chunk)) < count;)
      for (std::size_t i = c; i < std::min(c + chunk, count); ++i) f(i);
  };
  std::future<void> helper;
  if (count > chunk) helper = std::async(std::launch::async, work);
  work();
  if (helper.valid()) helper.get();
}

}  // namespace polarform
