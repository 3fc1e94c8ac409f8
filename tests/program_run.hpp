// Running a chapter program from a test: the shell command, its exit status and everything it
// printed (stdout and stderr together). Shared by the program tests and the fuzz test.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

struct ProgramRun {
  int status = -1;     // the exit status; -1 when the program ended by a signal
  std::string output;  // stdout and stderr together
};

inline ProgramRun run_command(const std::string& command) {
  ProgramRun r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return r;
  char buf[4096];
  while (fgets(buf, sizeof buf, pipe) != nullptr) r.output += buf;
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}
