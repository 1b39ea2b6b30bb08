// Runs a shell command line and collects its exit status and output (stdout + stderr).
#pragma once
#include <catch2/catch_test_macros.hpp>
#include <cstdio>
#include <string>

namespace testing {

struct Run {
  int status;
  std::string output;
};

inline Run run_command(const std::string& command_line) {
  Run r{0, ""};
  FILE* p = popen((command_line + " 2>&1").c_str(), "r");
  REQUIRE(p != nullptr);
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) r.output.append(buf, n);
  r.status = pclose(p);
  return r;
}

}  // namespace testing
