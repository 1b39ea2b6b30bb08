// What the live-capture tests share: the real take's files, the session and detector they run, waiting on a
// condition without asserting wall-clock speed.
#pragma once
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "octocap/octocap.h"

namespace testing {

inline const std::string kVideos =
    std::string(OCTOCAP_SOURCE_DIR) + "/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos/";
// The same views as H.264 camera streams (scripts/fetch-real-videos.sh), for the RTSP server.
inline const std::string kStreams = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/rtsp-streams/";
inline const std::string kDemo = std::string(OCTOCAP_REAL_DATA_DIR) + "/Demo";

inline std::vector<std::string> demo_videos() {
  std::vector<std::string> v;
  for (int c = 1; c <= 4; ++c) v.push_back(kVideos + "cam0" + std::to_string(c) + ".mp4");
  return v;
}

inline octocap_session_config_t coco_session() {
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.layout = OCTOCAP_LAYOUT_COCO_17;  // the shipped models' layout
  cfg.filter = OCTOCAP_FILTER_NONE;
  return cfg;
}

inline octocap_detector_config_t lightning() {
  octocap_detector_config_t det;
  octocap_detector_config_init(&det);
  std::snprintf(det.model, sizeof det.model, "%s", "movenet-lightning");  // the faster model: more sets per second
  return det;
}

inline double median_of(std::vector<double> v) {
  if (v.empty()) return 1e9;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// How long a network camera streams before its pictures' capture times come from the stream's own clock (two steady
// one-second windows, capture/stream_clock.h). Before that they are grab times, which on a loaded host pair pictures
// of different instants: by design, and not what an accuracy check should measure.
inline void let_stream_clocks_settle() { std::this_thread::sleep_for(std::chrono::milliseconds(2500)); }

template <class Pred>
bool wait_until(Pred&& done, int timeout_ms) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return done();
}

// Whether a server on loopback accepts connections on `port` within `timeout_ms`: a test's servers (a Python RTSP
// server imports GStreamer first, seconds on a cold machine) are up before the cameras that use them are opened.
inline bool port_accepts(int port, int timeout_ms) {
  return wait_until([&] {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return false;
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    const bool ok = connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0;
    close(fd);
    return ok;
  }, timeout_ms);
}

// `count` consecutive TCP ports a test's servers can listen on: below Linux's ephemeral range (32768-60999), where
// the kernel hands out the client ends of every connection on the machine (a port chosen in it was sometimes taken by
// the time a server bound it), spread by process id so parallel runs differ, and each checked free by binding it.
inline int free_port_run(int count) {
  auto bindable = [](int port) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return false;
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_ANY);
    const bool ok = bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0;
    close(fd);
    return ok;
  };
  constexpr int kLow = 12000, kSlots = (32768 - kLow) / 8;
  for (int attempt = 0; attempt < kSlots; ++attempt) {
    const int base = kLow + static_cast<int>((getpid() + attempt) % kSlots) * 8;
    bool all = true;
    for (int p = base; p < base + count && all; ++p) all = bindable(p);
    if (all) return base;
  }
  return 0;
}

// Takes up to `attempts` frames (2 s each) until `wanted` of them show the person in exactly `views` views; returns
// how many did.
template <class Live>
size_t frames_seen_by(Live& live, uint32_t views, size_t wanted, int attempts) {
  size_t seen = 0;
  for (int i = 0; i < attempts && seen < wanted; ++i)
    if (auto f = live.take(2000); f && f->person_count() == 1) seen += f->person(0).views_with_person == views;
  return seen;
}

}  // namespace testing
