#include "capture/multipart_reader.h"

#include <strings.h>

#include <cstdlib>

#include "core/error.h"

namespace octocap::internal {
namespace {

constexpr size_t kMaxHeaderBytes = 64u << 10;

size_t leading_dashes(const std::string& s, size_t from, size_t end) {
  size_t n = 0;
  while (from + n < end && s[from + n] == '-') ++n;
  return n;
}

std::string trim(std::string s) {
  const size_t a = s.find_first_not_of(" \t\"");
  const size_t b = s.find_last_not_of(" \t\"\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

}  // namespace

MultipartReader::MultipartReader(std::string boundary) {
  boundary = trim(boundary);
  // "--x" declared and "--x" sent, or "x" declared and "--x" sent: both are met in cameras; the dashes are left out of
  // the comparison.
  const size_t dashes = boundary.find_first_not_of('-');
  boundary_ = dashes == std::string::npos ? std::string() : boundary.substr(dashes);
}

void MultipartReader::feed(const char* data, size_t size) {
  buffer_.append(data, size);
  parse();
}

bool MultipartReader::take(std::vector<unsigned char>& body) {
  if (!has_newest_) return false;
  body.swap(newest_);
  has_newest_ = false;
  return true;
}

bool MultipartReader::delimiter_at(size_t line_start, size_t line_end) const {
  const size_t dashes = leading_dashes(buffer_, line_start, line_end);
  if (dashes < 2) return false;
  if (boundary_.empty()) return true;
  return buffer_.compare(line_start + dashes, boundary_.size(), boundary_) == 0;
}

void MultipartReader::finish_part(size_t begin, size_t end) {
  if (has_newest_) ++skipped_;  // never taken: a newer picture replaces it
  newest_.assign(buffer_.begin() + static_cast<std::ptrdiff_t>(begin), buffer_.begin() + static_cast<std::ptrdiff_t>(end));
  has_newest_ = true;
}

void MultipartReader::parse() {
  size_t pos = 0;  // bytes of buffer_ consumed
  for (;;) {
    if (state_ == State::body) {
      if (has_length_) {
        if (buffer_.size() - pos < content_length_) break;
        finish_part(pos, pos + content_length_);
        pos += content_length_;
        state_ = State::seeking_delimiter;
        continue;
      }
      // No Content-Length: the part ends at the newline before the next delimiter line.
      size_t end = std::string::npos;
      for (size_t nl = buffer_.find('\n', pos); nl != std::string::npos; nl = buffer_.find('\n', nl + 1)) {
        const size_t next = buffer_.find('\n', nl + 1);
        const size_t line_end = next == std::string::npos ? buffer_.size() : next;
        if (line_end - (nl + 1) < boundary_.size() + 2) {
          if (next == std::string::npos) break;  // too short to tell yet
          continue;
        }
        if (delimiter_at(nl + 1, line_end)) {
          end = nl;
          break;
        }
      }
      if (end == std::string::npos) {
        if (buffer_.size() - pos > kMaxPartBytes)
          throw Error(Errc::io, "a part grew past " + std::to_string(kMaxPartBytes >> 20) +
                                    " MB without its boundary: not a camera's picture");
        break;
      }
      finish_part(pos, end > pos && buffer_[end - 1] == '\r' ? end - 1 : end);
      pos = end + 1;
      state_ = State::seeking_delimiter;
      continue;
    }
    const size_t nl = buffer_.find('\n', pos);
    if (nl == std::string::npos) {
      if (buffer_.size() - pos > kMaxHeaderBytes)
        throw Error(Errc::io, "no part boundary or header end in " + std::to_string(kMaxHeaderBytes >> 10) +
                                  " KB: not a multipart MJPEG stream");
      break;
    }
    const size_t line_end = nl > pos && buffer_[nl - 1] == '\r' ? nl - 1 : nl;
    if (state_ == State::seeking_delimiter) {
      if (delimiter_at(pos, line_end)) {
        if (boundary_.empty()) {  // not declared: the first delimiter line says it
          const size_t dashes = leading_dashes(buffer_, pos, line_end);
          boundary_ = buffer_.substr(pos + dashes, line_end - pos - dashes);
        }
        state_ = State::headers;
        has_length_ = false;
        content_length_ = 0;
      }
    } else if (line_end == pos) {  // the blank line after the part's headers
      state_ = State::body;
    } else {
      const std::string line = buffer_.substr(pos, line_end - pos);
      const size_t colon = line.find(':');
      if (colon != std::string::npos && strncasecmp(line.c_str(), "content-length", colon) == 0 && colon == 14) {
        const std::string value = trim(line.substr(colon + 1));
        char* rest = nullptr;
        const unsigned long long n = std::strtoull(value.c_str(), &rest, 10);
        if (value.empty() || *rest != '\0' || value[0] == '-')
          throw Error(Errc::io, "a part's Content-Length is not a number: '" + value + "'");
        if (n > kMaxPartBytes)
          throw Error(Errc::io, "a part announces " + value + " bytes, more than any picture (" +
                                    std::to_string(kMaxPartBytes >> 20) + " MB at most)");
        content_length_ = static_cast<size_t>(n);
        has_length_ = true;
      }
    }
    pos = nl + 1;
  }
  buffer_.erase(0, pos);
}

}  // namespace octocap::internal
