#include "capture/mjpeg_http_source.h"

#include <strings.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <optional>
#include <vector>

#include <curl/curl.h>

#include "capture/jpeg_decoder.h"
#include "capture/multipart_reader.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/log.h"

namespace octocap::internal {
namespace {

constexpr int kMaxBadInARow = 30;  // about a second of a camera's pictures: the camera, not the wire, is at fault

void init_curl_once() {
  static const bool once = [] { return curl_global_init(CURL_GLOBAL_DEFAULT) == CURLE_OK; }();
  if (!once) throw Error(Errc::internal, "libcurl could not be initialised");
}

std::string header_value(const std::string& line, const char* name) {
  const size_t n = std::char_traits<char>::length(name);
  if (line.size() <= n || strncasecmp(line.c_str(), name, n) != 0 || line[n] != ':') return {};
  std::string v = line.substr(n + 1);
  v.erase(0, v.find_first_not_of(" \t"));
  while (!v.empty() && (v.back() == '\r' || v.back() == '\n' || v.back() == ' ')) v.pop_back();
  return v;
}

// boundary=... of a Content-Type, "" when absent.
std::string boundary_of(const std::string& content_type) {
  std::string lower = content_type;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const size_t at = lower.find("boundary=");
  if (at == std::string::npos) return {};
  std::string b = content_type.substr(at + 9);
  const size_t end = b.find(';');
  return end == std::string::npos ? b : b.substr(0, end);
}

class MjpegHttpSource : public FrameSource {
 public:
  MjpegHttpSource(CameraSpec spec, SourceOptions options) : spec_(std::move(spec)), options_(options) {
    init_curl_once();
    multi_ = curl_multi_init();
    if (multi_ == nullptr) throw Error(Errc::out_of_memory, "camera '" + spec_.text + "': cannot start a transfer");
  }
  ~MjpegHttpSource() override {
    close_transfer();
    curl_multi_cleanup(multi_);
  }

  void open() override {
    close_transfer();
    fallback_.reset();
    start_transfer();
    try {
      pump_until([&] { return decided_; }, options_.open_timeout_ms, "no answer");
    } catch (const Error& e) {
      close_transfer();
      throw Error(Errc::io, "camera '" + spec_.text + "': cannot be opened: " + e.what());
    }
    if (!reader_) {
      // Not an MJPEG stream: FFmpeg knows the other things a server may send.
      close_transfer();
      fallback_ = make_ffmpeg_source(spec_, options_);
      fallback_->open();
      return;
    }
    bad_in_a_row_ = 0;
  }

  bool read(cv::Mat& bgr, int64_t& stream_us) override {
    if (fallback_) return fallback_->read(bgr, stream_us);
    if (easy_ == nullptr || interrupted_) return false;
    const int64_t start_us = monotonic_us();
    for (;;) {
      const int left_ms = options_.read_timeout_ms - static_cast<int>((monotonic_us() - start_us) / 1000);
      try {
        pump_until([&] { return reader_->take(part_); }, std::max(left_ms, 0), "no picture");
      } catch (const Error&) {
        if (interrupted_) return false;
        throw;
      }
      stream_us = monotonic_us();  // arrival: an MJPEG part carries no time of its own
      if (decoder_.decode(part_, bgr)) {
        bad_in_a_row_ = 0;
        return true;
      }
      ++bad_;
      ++bad_in_a_row_;
      if (bad_ == 1 || bad_ % 100 == 0)
        log(LogLevel::warning, "camera '" + spec_.text + "': skipped " + (bad_ == 1 ? "a picture" : std::to_string(bad_) +
                               " pictures so far") + ": " + decoder_.why());
      if (bad_in_a_row_ >= kMaxBadInARow)
        throw Error(Errc::io, std::to_string(bad_in_a_row_) +
                                  " pictures in a row could not be used: " + decoder_.why());
    }
  }

  double nominal_fps() const override { return fallback_ ? fallback_->nominal_fps() : 0; }
  bool own_timestamps() const override { return fallback_ ? fallback_->own_timestamps() : false; }
  // Called on the camera's thread, as read(): the reader is not shared.
  uint64_t skipped() const override { return skipped_before_ + (reader_ ? reader_->skipped() : 0); }
  uint64_t bad_pictures() const override { return bad_; }

  void interrupt() override {
    interrupted_ = true;
    curl_multi_wakeup(multi_);  // thread-safe by libcurl's contract: ends a poll now
  }

 private:
  void start_transfer() {
    easy_ = curl_easy_init();
    if (easy_ == nullptr) throw Error(Errc::out_of_memory, "camera '" + spec_.text + "': cannot start a transfer");
    errbuf_[0] = '\0';
    decided_ = transfer_done_ = false;
    sniffed_.clear();
    content_type_.clear();
    callback_error_.clear();
    result_ = CURLE_OK;
    curl_easy_setopt(easy_, CURLOPT_URL, spec_.location.c_str());
    curl_easy_setopt(easy_, CURLOPT_NOSIGNAL, 1L);
    curl_easy_setopt(easy_, CURLOPT_ERRORBUFFER, errbuf_);
    curl_easy_setopt(easy_, CURLOPT_FAILONERROR, 1L);  // 404, 401: an error with its status, not a body to parse
    curl_easy_setopt(easy_, CURLOPT_FOLLOWLOCATION, 1L);
    curl_easy_setopt(easy_, CURLOPT_MAXREDIRS, 3L);
    curl_easy_setopt(easy_, CURLOPT_HTTPAUTH, static_cast<long>(CURLAUTH_ANY));  // user:pass@ in the URL, basic or digest
    curl_easy_setopt(easy_, CURLOPT_CONNECTTIMEOUT_MS, static_cast<long>(options_.open_timeout_ms));
    curl_easy_setopt(easy_, CURLOPT_BUFFERSIZE, 256L * 1024);  // drains a burst of pictures in few callbacks
    curl_easy_setopt(easy_, CURLOPT_USERAGENT, "octocap");
    curl_easy_setopt(easy_, CURLOPT_HEADERFUNCTION, &MjpegHttpSource::on_header);
    curl_easy_setopt(easy_, CURLOPT_HEADERDATA, this);
    curl_easy_setopt(easy_, CURLOPT_WRITEFUNCTION, &MjpegHttpSource::on_body);
    curl_easy_setopt(easy_, CURLOPT_WRITEDATA, this);
    curl_multi_add_handle(multi_, easy_);
  }

  void close_transfer() {
    if (easy_ == nullptr) return;
    if (reader_) skipped_before_ += reader_->skipped();
    reader_.reset();
    curl_multi_remove_handle(multi_, easy_);
    curl_easy_cleanup(easy_);
    easy_ = nullptr;
  }

  // Runs the transfer until `ready()`; throws Error naming why it cannot be (the transfer ended, `timeout_ms` passed:
  // "<none> in N s", a stop).
  template <class Ready>
  void pump_until(Ready&& ready, int timeout_ms, const char* none) {
    const int64_t deadline = monotonic_us() + timeout_ms * 1000LL;
    for (;;) {
      int running = 0;
      curl_multi_perform(multi_, &running);
      int queued = 0;
      while (CURLMsg* m = curl_multi_info_read(multi_, &queued))
        if (m->msg == CURLMSG_DONE) transfer_done_ = true, result_ = m->data.result;
      if (ready()) return;
      if (interrupted_) throw Error(Errc::io, "stopped");
      if (transfer_done_) throw Error(Errc::io, reason());
      const int64_t left_ms = (deadline - monotonic_us()) / 1000;
      if (left_ms <= 0) {
        char text[64];
        std::snprintf(text, sizeof text, "%s in %.1f s", none, timeout_ms / 1000.0);
        throw Error(Errc::io, text);
      }
      curl_multi_poll(multi_, nullptr, 0, static_cast<int>(std::min<int64_t>(left_ms, 250)), nullptr);
    }
  }

  std::string reason() const {
    if (!callback_error_.empty()) return callback_error_;
    if (result_ == CURLE_OK) return "the camera closed the connection";
    return errbuf_[0] != '\0' ? std::string(errbuf_) : std::string(curl_easy_strerror(result_));
  }

  static size_t on_header(char* data, size_t size, size_t count, void* self_) {
    auto* self = static_cast<MjpegHttpSource*>(self_);
    const std::string line(data, size * count);
    if (line.rfind("HTTP/", 0) == 0) {  // a new response (after a redirect or a 100): its headers start again
      self->content_type_.clear();
      self->status_ = 0;
      const size_t sp = line.find(' ');
      if (sp != std::string::npos) self->status_ = std::atoi(line.c_str() + sp + 1);
    } else if (line == "\r\n" || line == "\n") {
      // Made here, not in open(): the first part's bytes may come in the same transfer step as the headers.
      if (self->status_ >= 200 && self->status_ < 300 &&
          strncasecmp(self->content_type_.c_str(), "multipart/x-mixed-replace", 25) == 0)
        self->decide(true, boundary_of(self->content_type_));
      // Otherwise the body's first bytes decide (FFmpeg's own server calls its MJPEG application/octet-stream).
    } else if (const std::string type = header_value(line, "content-type"); !type.empty()) {
      self->content_type_ = type;
    }
    return size * count;
  }

  static size_t on_body(char* data, size_t size, size_t count, void* self_) {
    auto* self = static_cast<MjpegHttpSource*>(self_);
    const char* bytes = data;
    size_t n = size * count;
    if (!self->decided_) {
      // A multipart body starts with its first delimiter line, "--" (perhaps after a blank line).
      self->sniffed_.append(data, n);
      const size_t start = self->sniffed_.find_first_not_of("\r\n");
      if (start == std::string::npos || self->sniffed_.size() - start < 2) return n;
      self->decide(self->sniffed_.compare(start, 2, "--") == 0, "");
      bytes = self->sniffed_.data();
      n = self->sniffed_.size();
    }
    if (!self->reader_) return size * count;  // not multipart: open() hands the camera to FFmpeg
    try {  // nothing may be thrown through libcurl's C frames
      self->reader_->feed(bytes, n);
    } catch (const std::exception& e) {
      self->callback_error_ = e.what();
      return 0;  // ends the transfer
    }
    return size * count;
  }

  CameraSpec spec_;
  SourceOptions options_;
  CURLM* multi_ = nullptr;
  CURL* easy_ = nullptr;
  char errbuf_[CURL_ERROR_SIZE] = {};
  // A multipart body has a reader from now on; anything else none (open() then hands it to FFmpeg).
  void decide(bool multipart, const std::string& boundary) {
    decided_ = true;
    if (multipart) reader_.emplace(boundary);
  }

  bool decided_ = false, transfer_done_ = false;
  std::string sniffed_;  // the body's first bytes, while they decide what it is
  int status_ = 0;
  CURLcode result_ = CURLE_OK;
  std::string content_type_, callback_error_;
  std::optional<MultipartReader> reader_;
  std::vector<unsigned char> part_;
  JpegDecoder decoder_;
  std::unique_ptr<FrameSource> fallback_;
  std::atomic<bool> interrupted_{false};
  uint64_t bad_ = 0, skipped_before_ = 0;  // skipped_before_: by the readers of earlier connections
  int bad_in_a_row_ = 0;
};

}  // namespace

std::unique_ptr<FrameSource> make_mjpeg_http_source(const CameraSpec& spec, const SourceOptions& options) {
  return std::make_unique<MjpegHttpSource>(spec, options);
}

}  // namespace octocap::internal
