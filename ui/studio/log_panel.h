// The message log as a panel (every message, newest last, filter by severity, clear) and as
// toasts: the last few warnings and errors float over the bottom-right corner for a few seconds,
// so a failed action is noticed even with the log closed.
#pragma once

#include "ui/studio/message_log.h"

namespace polarform::studio {

class LogPanel {
 public:
  // The panel's contents (inside a window or child the caller opened).
  void draw(MessageLog& log);
  // Toasts over the main viewport.
  void draw_toasts(const MessageLog& log) const;

 private:
  bool show_info_ = true;
  std::size_t seen_ = 0;
};

}  // namespace polarform::studio
