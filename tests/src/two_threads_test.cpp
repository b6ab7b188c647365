// on_two_threads: every item done exactly once whatever the chunk, by the caller alone when the
// items fit one chunk, on two threads otherwise, and an item's exception reaches the caller.
#include "src/two_threads.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace polarform {
namespace {

TEST(TwoThreads, EveryItemOnceWhateverTheChunk) {
  for (const auto& [count, chunk] :
       {std::pair<std::size_t, std::size_t>{0, 1}, {1, 1}, {7, 1}, {513, 64}, {64, 64}, {100, 7}}) {
    std::vector<std::atomic<int>> done(count);
    on_two_threads(count, chunk, [&](std::size_t i) { ++done[i]; });
    for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(done[i].load(), 1) << count << " " << i;
  }
}

TEST(TwoThreads, TheCallerAloneWhenTheItemsFitOneChunk) {
  std::set<std::thread::id> ids;
  std::mutex m;
  on_two_threads(5, 5, [&](std::size_t) {
    std::lock_guard<std::mutex> lock(m);
    ids.insert(std::this_thread::get_id());
  });
  EXPECT_EQ(ids, std::set<std::thread::id>{std::this_thread::get_id()});
}

TEST(TwoThreads, AnItemsExceptionReachesTheCaller) {
  EXPECT_THROW(on_two_threads(100, 1,
                              [](std::size_t i) {
                                if (i == 57) throw std::runtime_error("item 57");
                              }),
               std::runtime_error);
}

}  // namespace
}  // namespace polarform
