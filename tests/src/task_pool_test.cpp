// The task pool: a task's result or exception reaches get(), a task nobody has taken runs on the
// thread that waits for it, a waiting thread runs other queued tasks meanwhile, and in_parallel
// does every item exactly once whatever the chunk, by the caller alone when the items fit one
// chunk.
#include "src/task_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace polarform {
namespace {

TEST(TaskPool, AtLeastOneThread) { EXPECT_GE(pool_threads(), 1u); }

TEST(TaskPool, ResultsAndExceptionsReachGet) {
  std::vector<Task<int>> tasks;
  for (int k = 0; k < 50; ++k)
    tasks.push_back(run_task([k] {
      if (k == 17) throw std::runtime_error("task 17");
      return k * k;
    }));
  for (int k = 0; k < 50; ++k)
    if (k == 17)
      EXPECT_THROW(tasks[k].get(), std::runtime_error);
    else
      EXPECT_EQ(tasks[k].get(), k * k);
  Task<void> nothing = run_task([] {});
  nothing.get();
  EXPECT_FALSE(nothing.valid());
}

// Every pool thread busy: a task queued behind them runs on the thread that waits for it.
TEST(TaskPool, ATaskNobodyTookRunsOnTheWaitingThread) {
  std::atomic<bool> release{false};
  std::atomic<std::size_t> started{0};
  std::vector<Task<void>> blockers;
  for (std::size_t k = 0; k < pool_threads(); ++k)
    blockers.push_back(run_task([&] {
      ++started;
      while (!release) std::this_thread::yield();
    }));
  while (started < pool_threads()) std::this_thread::yield();
  Task<std::thread::id> untaken = run_task([] { return std::this_thread::get_id(); });
  EXPECT_EQ(untaken.get(), std::this_thread::get_id());
  release = true;
}

// Every pool thread busy (one of them with `x`, which lasts until `queued` has run): `queued` is
// run by the thread that waits for `x`.
TEST(TaskPool, TheWaitingThreadRunsQueuedTasks) {
  std::atomic<bool> release{false}, queued_ran{false};
  std::atomic<std::size_t> started{0};
  std::vector<Task<void>> blockers;
  for (std::size_t k = 0; k + 1 < pool_threads(); ++k)
    blockers.push_back(run_task([&] {
      ++started;
      while (!release) std::this_thread::yield();
    }));
  Task<void> x = run_task([&] {
    ++started;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!queued_ran && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
  });
  while (started < pool_threads()) std::this_thread::yield();
  const std::thread::id me = std::this_thread::get_id();
  Task<std::thread::id> queued = run_task([&] {
    queued_ran = true;
    return std::this_thread::get_id();
  });
  x.get();
  EXPECT_TRUE(queued_ran.load());
  EXPECT_EQ(queued.get(), me);
  release = true;
}

TEST(TaskPool, DestroyingATaskWaitsForIt) {
  std::atomic<bool> finished{false};
  {
    Task<void> t = run_task([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      finished = true;
    });
  }
  EXPECT_TRUE(finished.load());
}

TEST(InParallel, EveryItemOnceWhateverTheChunk) {
  for (const auto& [count, chunk] :
       {std::pair<std::size_t, std::size_t>{0, 1}, {1, 1}, {7, 1}, {513, 64}, {64, 64}, {100, 7}}) {
    std::vector<std::atomic<int>> done(count);
    in_parallel(count, chunk, [&](std::size_t i) { ++done[i]; });
    for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(done[i].load(), 1) << count << " " << i;
  }
}

TEST(InParallel, TheCallerAloneWhenTheItemsFitOneChunk) {
  std::set<std::thread::id> ids;
  std::mutex m;
  in_parallel(5, 5, [&](std::size_t) {
    std::lock_guard<std::mutex> lock(m);
    ids.insert(std::this_thread::get_id());
  });
  EXPECT_EQ(ids, std::set<std::thread::id>{std::this_thread::get_id()});
}

TEST(InParallel, AnItemsExceptionReachesTheCaller) {
  EXPECT_THROW(in_parallel(100, 1,
                           [](std::size_t i) {
                             if (i == 57) throw std::runtime_error("item 57");
                           }),
               std::runtime_error);
}

}  // namespace
}  // namespace polarform
