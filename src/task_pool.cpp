#include "src/task_pool.h"

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace polarform {

namespace task_pool_detail {

namespace {

// The queue of tasks nobody has taken yet and the threads that take them; its lock guards every
// task's `taken` and `done`, and `changed` wakes the waiters on a new task or a finished one.
class Pool {
 public:
  Pool() {
    const unsigned cores = std::thread::hardware_concurrency();
    for (unsigned k = 0; k + 1 < std::max(cores, 2u); ++k)
      threads_.emplace_back([this] { serve(); });
  }
  ~Pool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      closing_ = true;
    }
    changed_.notify_all();
    for (std::thread& t : threads_) t.join();
  }
  Pool(const Pool&) = delete;
  Pool& operator=(const Pool&) = delete;

  std::size_t threads() const { return threads_.size(); }

  void submit(const std::shared_ptr<State>& task) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      queue_.push_back(task);
    }
    changed_.notify_all();
  }

  void wait(const std::shared_ptr<State>& task) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!task->taken) {
      for (auto i = queue_.begin(); i != queue_.end(); ++i)
        if (*i == task) {
          queue_.erase(i);
          break;
        }
      run(task, lock);
      return;
    }
    while (!task->done) {
      if (queue_.empty()) {
        changed_.wait(lock);
        continue;
      }
      const std::shared_ptr<State> other = std::move(queue_.front());
      queue_.pop_front();
      run(other, lock);
    }
  }

 private:
  // Runs a task taken off the queue (the lock held on entry and exit, released while it runs).
  void run(const std::shared_ptr<State>& task, std::unique_lock<std::mutex>& lock) {
    task->taken = true;
    lock.unlock();
    task->body();
    task->body = nullptr;  // what it holds goes with it, on this thread
    lock.lock();
    task->done = true;
    changed_.notify_all();
  }

  void serve() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      changed_.wait(lock, [this] { return closing_ || !queue_.empty(); });
      if (queue_.empty()) return;  // closing
      const std::shared_ptr<State> task = std::move(queue_.front());
      queue_.pop_front();
      run(task, lock);
    }
  }

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::shared_ptr<State>> queue_;
  bool closing_ = false;
  std::vector<std::thread> threads_;
};

Pool& pool() {
  static Pool instance;
  return instance;
}

}  // namespace

void submit(const std::shared_ptr<State>& task) { pool().submit(task); }

void wait(const std::shared_ptr<State>& task) { pool().wait(task); }

}  // namespace task_pool_detail

std::size_t pool_threads() { return task_pool_detail::pool().threads(); }

}  // namespace polarform
