// Costly independent work (a conversion's product beside its refit, the refit's degrees, R's
// evaluations at a table's nodes, a curve's error over each arc) shared by the calling thread and
// a pool of one thread per further core. A thread that waits for a task runs it itself if no one
// has taken it yet, and runs other queued tasks meanwhile otherwise (work helping): no more
// threads are runnable than there are cores, and no core idles while work is queued. (A thread
// per task left that to the kernel, which on 2 cores ran a conversion's four knot placements
// one after another on one core while the other idled.)
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace polarform {

namespace task_pool_detail {

struct State {
  std::function<void()> body;  // the task; stores its result or its exception
  std::exception_ptr error;
  bool taken = false, done = false;  // guarded by the pool's lock
};

// Queues the task for the pool's threads.
void submit(const std::shared_ptr<State>& task);
// Returns once the task is done: runs it if it is still queued, else runs other queued tasks
// (or sleeps) until it is.
void wait(const std::shared_ptr<State>& task);

}  // namespace task_pool_detail

// The pool's threads: one per core beyond the first (at least one).
std::size_t pool_threads();

// The result of run_task: get() waits for it (helping, as above) and returns it or rethrows the
// task's exception. Destroying a Task waits for it too, so that it never outlives what it uses.
template <class T>
class Task {
 public:
  Task() = default;
  Task(Task&&) noexcept = default;
  Task& operator=(Task&& other) noexcept {
    finish();
    state_ = std::move(other.state_), value_ = std::move(other.value_);
    return *this;
  }
  Task(const Task&) = delete;
  Task& operator=(const Task&) = delete;
  ~Task() { finish(); }

  bool valid() const { return state_ != nullptr; }

  // Once; the Task is empty afterwards.
  T get() {
    const std::shared_ptr<task_pool_detail::State> state = std::move(state_);
    task_pool_detail::wait(state);
    if (state->error) std::rethrow_exception(state->error);
    if constexpr (!std::is_void_v<T>) return std::move(**value_);
  }

 private:
  template <class F>
  friend Task<std::invoke_result_t<F&>> run_task(F f);

  void finish() noexcept {
    if (state_) task_pool_detail::wait(state_);
    state_.reset();
  }

  struct Nothing {};
  using Slot = std::optional<std::conditional_t<std::is_void_v<T>, Nothing, T>>;
  std::shared_ptr<task_pool_detail::State> state_;
  std::shared_ptr<Slot> value_ = std::make_shared<Slot>();
};

// f() as a task on the pool (or on the thread that waits for it). f and what it refers to must
// outlive the Task.
template <class F>
Task<std::invoke_result_t<F&>> run_task(F f) {
  using T = std::invoke_result_t<F&>;
  Task<T> task;
  auto state = std::make_shared<task_pool_detail::State>();
  state->body = [f = std::move(f), value = task.value_, raw = state.get()]() mutable {
    try {
      if constexpr (std::is_void_v<T>)
        f();
      else
        value->emplace(f());
    } catch (...) {
      raw->error = std::current_exception();
    }
  };
  task.state_ = state;
  task_pool_detail::submit(state);
  return task;
}

// f(i) for i = 0..count − 1, the items taken `chunk` at a time from a shared counter by the caller
// and up to pool_threads() helpers, so that all finish together whatever each item costs; the
// caller alone when count <= chunk. f must be safe to call concurrently for different i; an
// exception from an item reaches the caller (after every thread has stopped taking items).
template <class F>
void in_parallel(std::size_t count, std::size_t chunk, const F& f) {
  chunk = std::max<std::size_t>(chunk, 1);
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t c; (c = next.fetch_add(chunk)) < count;)
      for (std::size_t i = c; i < std::min(c + chunk, count); ++i) f(i);
  };
  const std::size_t chunks = (count + chunk - 1) / chunk;
  std::vector<Task<void>> helpers;
  for (std::size_t h = 0; h + 1 < std::min(chunks, pool_threads() + 1); ++h)
    helpers.push_back(run_task(work));
  std::exception_ptr error;
  try {
    work();
  } catch (...) {
    error = std::current_exception();
    next = count;  // the helpers stop taking items
  }
  for (Task<void>& h : helpers) try {
      h.get();
    } catch (...) {
      if (!error) error = std::current_exception();
    }
  if (error) std::rethrow_exception(error);
}

}  // namespace polarform
