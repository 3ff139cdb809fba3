// Runs the `drape` binary (test::DrapeCli(), set by the test build) through the
// shell, as a user or a script would, and captures what it prints.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include "support/test_paths.h"

namespace drape::test {

struct CommandResult {
  int exit_code;
  std::string output;
};

enum class Captured { kBoth, kStdout, kStderr };

// A shell command; stderr is not a terminal.
inline CommandResult RunCommand(const std::string& shell_command,
                                Captured captured = Captured::kBoth) {
  const char* redirect = captured == Captured::kBoth     ? " 2>&1"
                         : captured == Captured::kStdout ? " 2>/dev/null"
                                                         : " 2>&1 >/dev/null";
  const std::string command = "{ " + shell_command + "; }" + redirect;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return {-1, "popen failed"};
  std::string output;
  std::array<char, 4096> buffer;
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

// `drape ARGUMENTS`.
inline CommandResult RunDrape(const std::string& arguments, Captured captured = Captured::kBoth) {
  return RunCommand(std::string(test::DrapeCli()) + " " + arguments, captured);
}

}  // namespace drape::test
