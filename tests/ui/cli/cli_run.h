// Running the polarform binary as a user would, for the CLI tests of the cam and study commands:
// each argument passed verbatim through /bin/sh, the exit status, stdout and stderr captured.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/jobs/cam_job_support.h"

namespace polarform::cam_job_test {

inline const fs::path kCli = fs::path(POLARFORM_BINARY_DIR) / "ui" / "cli" / "polarform";

struct CliRun {
  int status = -1;  // exit status; 128 + signal when the tool was killed by a signal
  std::string out, err;
};

// Runs the polarform CLI with the arguments (each passed verbatim) through /bin/sh, capturing
// stdout and stderr in files of `scratch`.
inline CliRun run_cli(const std::vector<std::string>& args, const ScratchDir& scratch) {
  auto quote = [](const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  std::string command = quote(kCli.string());
  for (const std::string& a : args) command += " " + quote(a);
  const fs::path out = scratch / "cli_stdout.txt", err = scratch / "cli_stderr.txt";
  command += " >" + quote(out.string()) + " 2>" + quote(err.string());
  const int raw = std::system(command.c_str());
  CliRun run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  run.out = slurp(out);
  run.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return run;
}

}  // namespace polarform::cam_job_test
