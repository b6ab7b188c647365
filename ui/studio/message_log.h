// MessageLog: what the app tells the user — errors from bad input, warnings from project files,
// notes about finished jobs — kept in order with a timestamp. The log panel lists them; the newest
// ones also appear briefly as toasts. Thread-safe: background jobs may report too.
#pragma once

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

namespace polarform::studio {

enum class Severity { info, warning, error };

struct Message {
  Severity severity = Severity::info;
  std::string text;
  std::chrono::steady_clock::time_point time;
};

class MessageLog {
 public:
  void add(Severity severity, std::string text);
  void info(std::string text) { add(Severity::info, std::move(text)); }
  void warning(std::string text) { add(Severity::warning, std::move(text)); }
  void error(std::string text) { add(Severity::error, std::move(text)); }

  // A copy of every message, oldest first.
  std::vector<Message> messages() const;
  std::size_t size() const;
  std::size_t error_count() const;
  void clear();

 private:
  mutable std::mutex mutex_;
  std::vector<Message> messages_;
};

}  // namespace polarform::studio
