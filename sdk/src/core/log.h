// The library's log: one process-wide sink set through the C ABI; nothing is printed by the library.
#pragma once
#include <functional>
#include <string>

namespace octocap::internal {

enum class LogLevel : int { debug = 0, info = 1, warning = 2, error = 3 };
using LogSink = std::function<void(LogLevel, const char*)>;

void set_log_sink(LogSink sink, LogLevel min_level);
void log(LogLevel level, const std::string& message);

}  // namespace octocap::internal
