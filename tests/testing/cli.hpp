#pragma once
// Runs the armstudy command as a user would (the ARMSTUDY_BINARY the test target defines),
// standard input closed, and returns its exit code and its standard output and error.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace armstudy::testing {

struct CliRun {
  int exit_code;
  std::string output;  ///< standard output and standard error, interleaved
};

/// `armstudy ARGS 2>&1 </dev/null`; exit_code -1 when it did not exit normally.
inline CliRun run_cli(const std::string& args) {
  const std::string cmd = std::string(ARMSTUDY_BINARY) + " " + args + " 2>&1 </dev/null";
  CliRun r{-1, ""};
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (p && fgets(buf.data(), buf.size(), p)) r.output += buf.data();
  const int status = p ? pclose(p) : -1;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace armstudy::testing
