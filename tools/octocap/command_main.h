// Every subcommand's last line of defence: an error (the library's, or the file system's) becomes one message and
// exit status 1, never an abort.
#pragma once
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "octocap/octocap.h"

// The library's warnings (folders of different lengths cut, a camera left out), as the subcommands print them.
inline void print_library_log(octocap_log_level_t level, const char* message, void*) {
  static const char* names[] = {"debug", "info", "warning", "error"};
  std::fprintf(stderr, "octocap %s: %s\n", level >= 0 && level <= 3 ? names[level] : "log", message);
}

// --rate as the library's files take it (motion_files: 0.001 to 100000 Hz); `zero_allowed`: 0 has a meaning (the
// frames' own timestamps).
inline void check_rate_option(double rate_hz, bool zero_allowed) {
  if (!std::isfinite(rate_hz) || ((rate_hz != 0 || !zero_allowed) && (rate_hz < 1e-3 || rate_hz > 1e5)))
    throw std::runtime_error("--rate must be between 0.001 and 100000 Hz");
}

template <class Options, class Command>
int run_reporting_errors(const char* name, const Options& options, Command&& command) {
  try {
    return command(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "octocap %s: error: %s\n", name, e.what());
    return 1;
  }
}
