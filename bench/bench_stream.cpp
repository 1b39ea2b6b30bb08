// Streaming benchmark: publish -> receive latency (p50, p99) and delivery at 60, 120 and 1000 Hz for the
// skeleton sample (25 keypoints, 15 joints, 13 bones), both QoS profiles, over loopback, plain and over DDS Security
// (a throwaway keystore: authenticated, everything encrypted). Plain: publisher and subscriber are two participants in
// one process. Secure: the publisher is a forked process with the hub's identity (Cyclone keeps one security
// configuration per domain and process), the subscriber here with a viewer's; the monotonic clock is the host's, so
// latency is exact either way.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <unistd.h>
#include <vector>
#include <filesystem>
#include <string>
#include <sys/wait.h>

#include "stream/dds_publisher.h"
#include "stream/keystore.h"
#include "stream/dds_subscriber.h"
#include "loopback_dds.h"

using namespace octocap::internal;
using Clock = std::chrono::steady_clock;

namespace {

int64_t now_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(Clock::now().time_since_epoch()).count();
}

FrameResult sample_frame() {
  FrameResult f;
  f.layout = LayoutId::body25;
  PersonResult p;
  p.keypoints.resize(25);
  for (auto& k : p.keypoints) {
    k.valid = true;
    k.position = Eigen::Vector3d(0.1, 1.2, 0.3);
    k.views_used = 4;
  }
  for (auto& j : p.joints) j = p.keypoints[0];
  for (auto& b : p.bones) {
    b.valid = true;
    b.length = 0.3;
  }
  f.blank.keypoints.resize(25);
  f.people.push_back(p);
  return f;
}

// Two seconds of frames at `hz`, stamped with the monotonic clock when published.
void publish_frames(DdsPublisher& pub, double hz, int frames) {
  FrameResult f = sample_frame();
  const auto start = Clock::now();
  for (int i = 0; i < frames; ++i) {
    std::this_thread::sleep_until(start + std::chrono::microseconds(static_cast<int64_t>(i * 1e6 / hz)));
    f.info.frame_index = i;
    f.info.timestamp_us = now_us();
    pub.publish(f);
  }
  pub.flush();
}

// The keystore of the secure rows: "" for the plain ones.
struct Security {
  std::string publisher, subscriber;
};

void run(double hz, StreamQos qos, uint32_t domain, const Security& security) {
  StreamConfig cfg;
  cfg.domain_id = domain;
  cfg.qos = qos;
  cfg.topic = "bench_" + std::to_string(static_cast<int>(hz)) + (qos == StreamQos::record ? "_rec" : "_live");
  const int frames = static_cast<int>(hz * 2);  // two seconds
  const bool secure = !security.publisher.empty();
  pid_t child = -1;
  if (secure) {
    std::fflush(stdout);
    child = fork();
    if (child == 0) {
      StreamConfig pc = cfg;
      pc.security = security.publisher;
      DdsPublisher pub(pc, LayoutId::body25);
      std::this_thread::sleep_for(std::chrono::milliseconds(2500));  // discovery and the handshake
      publish_frames(pub, hz, frames);
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      _exit(0);
    }
  }
  StreamConfig sc = cfg;
  sc.security = security.subscriber;
  DdsSubscriber sub(sc);
  std::unique_ptr<DdsPublisher> pub;
  if (!secure) pub = std::make_unique<DdsPublisher>(cfg, LayoutId::body25);
  if (!secure) std::this_thread::sleep_for(std::chrono::milliseconds(800));  // discovery
  std::vector<double> latency;
  std::atomic<bool> done{false};
  std::thread receiver([&] {
    int idle = 0;
    while (latency.size() < static_cast<size_t>(frames)) {
      if (!sub.take_next(300)) {
        if (done.load() || (secure && ++idle > 20)) break;
        continue;
      }
      idle = 0;
      latency.push_back(static_cast<double>(now_us() - sub.frame().info.timestamp_us));
    }
  });
  if (pub) publish_frames(*pub, hz, frames);
  if (secure) waitpid(child, nullptr, 0);
  done = true;
  receiver.join();
  std::sort(latency.begin(), latency.end());
  auto pct = [&](double p) { return latency.empty() ? 0.0 : latency[static_cast<size_t>(p * (latency.size() - 1))]; };
  std::printf("%6.0f Hz  %-6s %-6s | sent %5d  received %5zu (%5.1f%%)  lost %4llu | latency p50 %6.0f us  p99 %6.0f us\n",
              hz, qos == StreamQos::record ? "record" : "live", secure ? "secure" : "plain", frames, latency.size(),
              100.0 * latency.size() / frames, static_cast<unsigned long long>(sub.stats().frames_lost), pct(0.5),
              pct(0.99));
}

}  // namespace

int main() {
  std::printf("octocap stream benchmark: skeleton pose sample (25 keypoints, 15 joints, 13 bones), loopback,\n"
              "publish() call -> subscriber take, 2 s per row; secure: DDS Security, authenticated and encrypted\n\n");
  const uint32_t domain = testing::loopback_dds_domain();
  for (StreamQos qos : {StreamQos::live, StreamQos::record})
    for (double hz : {60.0, 120.0, 1000.0}) run(hz, qos, domain, {});
  // Secure rows in a domain of their own: this process's participants there all carry the viewer's identity.
  char pattern[] = "/tmp/octocap-bench-keystore-XXXXXX";
  const std::string keystore = std::string(mkdtemp(pattern)) + "/studio";
  create_keystore(keystore, 1);
  add_identity(keystore, "hub", SecurityRole::hub, 1);
  add_identity(keystore, "viewer", SecurityRole::viewer, 1);
  const Security security{keystore + "/hub", keystore + "/viewer"};
  for (StreamQos qos : {StreamQos::live, StreamQos::record})
    for (double hz : {60.0, 120.0, 1000.0}) run(hz, qos, (domain + 1) % 200 + 1, security);
  std::filesystem::remove_all(std::filesystem::path(keystore).parent_path());
  return 0;
}
