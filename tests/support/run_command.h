// Running a program from a test: its exit code and everything it printed.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace pw::test {

struct CommandRun {
  int exitCode = -1;   // -1: it could not be started or did not exit normally
  std::string output;  // stdout and stderr
};

// Runs `command` through the shell, stderr merged into stdout.
inline CommandRun runCommand(const std::string& command) {
  CommandRun run;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace pw::test
