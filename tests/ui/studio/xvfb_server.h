// One Xvfb server for the studio tests of one test process: started with -displayfd, so that the X
// server itself picks a free display number (race-free, however many test processes start at
// once), and stopped with the process. The studio runs on it through DISPLAY; no xvfb-run, whose
// display guessing and temporary-directory clean-up failed under ctest -j.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <optional>
#include <string>

namespace polarform::studio_test {

class XvfbServer {
 public:
  // Starts `Xvfb -displayfd` with a 1920x1200x24 screen; display() is empty when Xvfb is missing
  // or did not report a display within 10 s.
  XvfbServer() {
    int fds[2];
    if (::pipe(fds) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::close(fds[0]);
      const int null = ::open("/dev/null", O_RDWR);
      ::dup2(null, 0), ::dup2(null, 1), ::dup2(null, 2);
      const std::string fd = std::to_string(fds[1]);
      ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1920x1200x24",
               "-nolisten", "tcp", "-noreset", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    if (pid_ < 0) {
      ::close(fds[0]);
      return;
    }
    std::string number;
    pollfd p{fds[0], POLLIN, 0};
    char c = 0;
    while (::poll(&p, 1, 10000) > 0 && ::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (!number.empty() && number.find_first_not_of("0123456789") == std::string::npos)
      display_ = ":" + number;
  }
  ~XvfbServer() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  XvfbServer(const XvfbServer&) = delete;
  XvfbServer& operator=(const XvfbServer&) = delete;

  const std::optional<std::string>& display() const { return display_; }

 private:
  pid_t pid_ = -1;
  std::optional<std::string> display_;
};

}  // namespace polarform::studio_test
