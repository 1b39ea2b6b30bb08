#include "core/log.h"

#include <mutex>

#include "core/redact.h"

namespace octocap::internal {
namespace {

std::mutex g_mutex;
LogSink g_sink;
LogLevel g_min = LogLevel::info;

}  // namespace

void set_log_sink(LogSink sink, LogLevel min_level) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_sink = std::move(sink);
  g_min = min_level;
}

void log(LogLevel level, const std::string& message) {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (g_sink && level >= g_min) g_sink(level, redact_credentials(message).c_str());
}

}  // namespace octocap::internal
