// Runs one long computation (reading a scan, a surface fit, a vessel solve, a study) on a worker
// thread so the UI keeps drawing: progress in [0, 1], cooperative cancel (the work's progress
// reports throw TaskCancelled once cancel is asked), and the outcome — value, error or
// cancellation — collected by the UI thread. Starting while busy cancels the running work and
// queues the new one (latest wins).
#pragma once

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace polarform::studio {

struct TaskCancelled : std::exception {
  const char* what() const noexcept override { return "cancelled"; }
};

// Handed to the work: report progress (and be interrupted there).
class TaskControl {
 public:
  void report(double fraction) {
    progress_.store(fraction, std::memory_order_relaxed);
    if (cancel_.load(std::memory_order_relaxed)) throw TaskCancelled();
  }
  bool cancelled() const { return cancel_.load(std::memory_order_relaxed); }

 private:
  template <class R>
  friend class BackgroundTask;
  std::atomic<double> progress_{0.0};
  std::atomic<bool> cancel_{false};
};

template <class R>
struct TaskOutcome {
  std::optional<R> value;    // set on success
  std::exception_ptr error;  // set on failure
  bool cancelled = false;
  double seconds = 0.0;  // wall time of the work
};

template <class R>
class BackgroundTask {
 public:
  using Work = std::function<R(TaskControl&)>;

  BackgroundTask() = default;
  ~BackgroundTask() {
    cancel();
    if (thread_.joinable()) thread_.join();
  }
  BackgroundTask(const BackgroundTask&) = delete;
  BackgroundTask& operator=(const BackgroundTask&) = delete;

  void start(Work work) {
    if (busy()) {
      pending_ = std::move(work);
      cancel();
      return;
    }
    launch(std::move(work));
  }
  void cancel() { control_.cancel_.store(true); }
  // Running or queued.
  bool busy() const { return thread_.joinable() || pending_.has_value(); }
  double progress() const { return control_.progress_.load(std::memory_order_relaxed); }

  // The outcome of finished work, once; starts queued work. Call every frame.
  std::optional<TaskOutcome<R>> poll() {
    if (!thread_.joinable() || !done_.load()) return std::nullopt;
    thread_.join();
    TaskOutcome<R> outcome;
    {
      std::lock_guard lock(mutex_);
      outcome = std::move(outcome_);
    }
    if (pending_) {
      launch(std::move(*pending_));
      pending_.reset();
      return std::nullopt;  // superseded
    }
    return outcome;
  }

 private:
  void launch(Work work) {
    control_.progress_.store(0.0);
    control_.cancel_.store(false);
    done_.store(false);
    thread_ = std::thread([this, work = std::move(work)] {
      const auto start = std::chrono::steady_clock::now();
      TaskOutcome<R> outcome;
      try {
        outcome.value.emplace(work(control_));
      } catch (const TaskCancelled&) {
        outcome.cancelled = true;
      } catch (...) {
        outcome.error = std::current_exception();
      }
      outcome.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      {
        std::lock_guard lock(mutex_);
        outcome_ = std::move(outcome);
      }
      done_.store(true);
    });
  }

  TaskControl control_;
  std::thread thread_;
  std::atomic<bool> done_{false};
  std::mutex mutex_;
  TaskOutcome<R> outcome_;
  std::optional<Work> pending_;
};

}  // namespace polarform::studio
