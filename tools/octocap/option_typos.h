// A mistyped option named before CLI11's own checks run: CLI11 reports a missing required option first ("--output is
// required" for `--outptu x`), which hides the real mistake. Each "--word" that the subcommand does not know is told,
// with the nearest option it does know.
#pragma once
#include <CLI/CLI.hpp>

// 0 when every option is known; else prints what is wrong and returns 2 (the usage error status).
int report_unknown_options(const CLI::App& app, int argc, char** argv);
