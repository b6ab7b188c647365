#include "ui/studio/message_log.h"

#include <algorithm>
#include <iostream>

namespace polarform::studio {

void MessageLog::add(Severity severity, std::string text) {
  // Also on stderr, so headless runs (screenshots, benchmarks, tests) show what went wrong.
  if (severity != Severity::info) std::cerr << "polarform-studio: " << text << "\n";
  std::lock_guard lock(mutex_);
  messages_.push_back({severity, std::move(text), std::chrono::steady_clock::now()});
}

std::vector<Message> MessageLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

std::size_t MessageLog::size() const {
  std::lock_guard lock(mutex_);
  return messages_.size();
}

std::size_t MessageLog::error_count() const {
  std::lock_guard lock(mutex_);
  return static_cast<std::size_t>(
      std::count_if(messages_.begin(), messages_.end(),
                    [](const Message& m) { return m.severity == Severity::error; }));
}

void MessageLog::clear() {
  std::lock_guard lock(mutex_);
  messages_.clear();
}

}  // namespace polarform::studio
