#include "core/redact.h"

#include <cstring>

namespace octocap::internal {

std::string redact_credentials(const std::string& text) {
  std::string out;
  size_t from = 0;
  for (;;) {
    const size_t scheme = text.find("://", from);
    if (scheme == std::string::npos) break;
    const size_t start = scheme + 3;
    // The authority (user:password@host:port) ends where the path, query or fragment starts, or where the text
    // around the URL does (a space, a quote).
    size_t end = start;
    while (end < text.size() && !std::strchr("/?# \t\r\n'\"<>", text[end])) ++end;
    const size_t at = end > start ? text.rfind('@', end - 1) : std::string::npos;
    const size_t colon = text.find(':', start);
    if (at != std::string::npos && at >= start && colon < at) {
      out.append(text, from, colon + 1 - from);
      out += "***";
      out.append(text, at, end - at);
    } else {
      out.append(text, from, end - from);
    }
    from = end;
  }
  out.append(text, from, std::string::npos);
  return out;
}

}  // namespace octocap::internal
