#include "capi/boundary.h"

#include <cstring>

#include "core/log.h"
#include "core/redact.h"

namespace octocap::internal::capi {
namespace {
thread_local std::string t_last_error;
}

void set_last_error(const std::string& message) { t_last_error = redact_credentials(message); }
void clear_last_error() { t_last_error.clear(); }

std::string c_text(const char* src, size_t capacity, const char* what) {
  const size_t len = strnlen(src, capacity);
  if (len == capacity) throw Error(Errc::invalid_argument, std::string(what) + " is not NUL-terminated");
  return std::string(src, len);
}

void copy_name(char* dst, size_t capacity, const std::string& src) {
  if (capacity == 0) return;
  const size_t n = std::min(capacity - 1, src.size());
  std::memcpy(dst, src.data(), n);
  std::memset(dst + n, 0, capacity - n);
}

}  // namespace octocap::internal::capi

using namespace octocap::internal;

extern "C" {

const char* octocap_version(void) { return OCTOCAP_VERSION_STRING; }
uint32_t octocap_abi_version(void) { return OCTOCAP_ABI_VERSION; }
uint32_t octocap_version_number(void) { return OCTOCAP_VERSION_NUMBER; }
const char* octocap_last_error(void) { return capi::t_last_error.c_str(); }

const char* octocap_redact_credentials(const char* text) {
  static thread_local std::string redacted;
  try {
    redacted = text ? redact_credentials(text) : std::string();
  } catch (...) {  // out of memory: nothing rather than the secret
    redacted.clear();
  }
  return redacted.c_str();
}

const char* octocap_result_name(octocap_result_t r) {
  switch (r) {
    case OCTOCAP_OK: return "OCTOCAP_OK";
    case OCTOCAP_STATUS_NO_PERSON: return "OCTOCAP_STATUS_NO_PERSON";
    case OCTOCAP_STATUS_TIMEOUT: return "OCTOCAP_STATUS_TIMEOUT";
    case OCTOCAP_ERROR_OUT_OF_MEMORY: return "OCTOCAP_ERROR_OUT_OF_MEMORY";
    case OCTOCAP_ERROR_INVALID_ARGUMENT: return "OCTOCAP_ERROR_INVALID_ARGUMENT";
    case OCTOCAP_ERROR_INVALID_HANDLE: return "OCTOCAP_ERROR_INVALID_HANDLE";
    case OCTOCAP_ERROR_STRUCT_SIZE: return "OCTOCAP_ERROR_STRUCT_SIZE";
    case OCTOCAP_ERROR_IO: return "OCTOCAP_ERROR_IO";
    case OCTOCAP_ERROR_PARSE: return "OCTOCAP_ERROR_PARSE";
    case OCTOCAP_ERROR_BUFFER_TOO_SMALL: return "OCTOCAP_ERROR_BUFFER_TOO_SMALL";
    case OCTOCAP_ERROR_CAMERA_MISMATCH: return "OCTOCAP_ERROR_CAMERA_MISMATCH";
    case OCTOCAP_ERROR_NOT_ENOUGH_VIEWS: return "OCTOCAP_ERROR_NOT_ENOUGH_VIEWS";
    case OCTOCAP_ERROR_NO_RESULT: return "OCTOCAP_ERROR_NO_RESULT";
    case OCTOCAP_ERROR_UNSUPPORTED: return "OCTOCAP_ERROR_UNSUPPORTED";
    case OCTOCAP_ERROR_INTERNAL: return "OCTOCAP_ERROR_INTERNAL";
  }
  return "OCTOCAP_UNKNOWN_RESULT";
}

void octocap_set_log_callback(octocap_log_callback_t callback, octocap_log_level_t min_level, void* user) {
  if (!callback) {
    set_log_sink(nullptr, LogLevel::error);
    return;
  }
  set_log_sink([callback, user](LogLevel level, const char* message) {
    callback(static_cast<octocap_log_level_t>(level), message, user);
  }, static_cast<LogLevel>(min_level));
}

}  // extern "C"
