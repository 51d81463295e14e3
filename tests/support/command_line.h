#pragma once
// Running a command from a test: its exit status and everything it printed, for tests of
// the command line.

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace caskdem::testing {

struct Outcome {
  int status = 0;      // exit status; -1 when the command did not exit (a signal)
  std::string output;  // stdout and stderr together
};

inline Outcome run_shell(const std::string& command) {
  Outcome o;
  std::FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) o.output += buffer;
  const int raw = pclose(pipe);
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return o;
}

// The caskdem binary built beside the tests.
inline Outcome run_caskdem(const std::string& arguments) {
  return run_shell(std::string(CASKDEM_BINARY) + " " + arguments);
}

}  // namespace caskdem::testing
