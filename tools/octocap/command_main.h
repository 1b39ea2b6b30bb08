// Every subcommand's last line of defence: an error (the library's, or the file system's) becomes one message and
// exit status 1, never an abort.
#pragma once
#include <cstdio>
#include <exception>

template <class Options, class Command>
int run_reporting_errors(const char* name, const Options& options, Command&& command) {
  try {
    return command(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "octocap %s: error: %s\n", name, e.what());
    return 1;
  }
}
