// Streaming benchmark: publish -> receive latency (p50, p99) and delivery at 60, 120 and 1000 Hz for the
// skeleton sample (25 keypoints, 15 joints, 13 bones), both QoS profiles, over loopback. Publisher and
// subscriber are separate DDS participants in one process (the clock is shared, so latency is exact).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <unistd.h>
#include <vector>

#include "stream/dds_publisher.h"
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

void run(double hz, StreamQos qos, uint32_t domain) {
  StreamConfig cfg;
  cfg.domain_id = domain;
  cfg.qos = qos;
  cfg.topic = "bench_" + std::to_string(static_cast<int>(hz)) + (qos == StreamQos::record ? "_rec" : "_live");
  DdsSubscriber sub(cfg);
  DdsPublisher pub(cfg, LayoutId::body25);
  std::this_thread::sleep_for(std::chrono::milliseconds(800));  // discovery
  const int frames = static_cast<int>(hz * 2);  // two seconds
  std::vector<double> latency;
  std::atomic<bool> done{false};
  std::thread receiver([&] {
    while (!done.load() || latency.size() < static_cast<size_t>(frames)) {
      if (!sub.take_next(300)) {
        if (done.load()) break;
        continue;
      }
      latency.push_back(static_cast<double>(now_us() - sub.frame().info.timestamp_us));
    }
  });
  FrameResult f = sample_frame();
  const auto start = Clock::now();
  for (int i = 0; i < frames; ++i) {
    std::this_thread::sleep_until(start + std::chrono::microseconds(static_cast<int64_t>(i * 1e6 / hz)));
    f.info.frame_index = i;
    f.info.timestamp_us = now_us();
    pub.publish(f);
  }
  pub.flush();
  done = true;
  receiver.join();
  std::sort(latency.begin(), latency.end());
  auto pct = [&](double p) { return latency.empty() ? 0.0 : latency[static_cast<size_t>(p * (latency.size() - 1))]; };
  std::printf("%6.0f Hz  %-6s | sent %5d  received %5zu (%5.1f%%)  lost %4llu | latency p50 %6.0f us  p99 %6.0f us\n",
              hz, qos == StreamQos::record ? "record" : "live", frames, latency.size(), 100.0 * latency.size() / frames,
              static_cast<unsigned long long>(sub.stats().frames_lost), pct(0.5), pct(0.99));
}

}  // namespace

int main() {
  std::printf("octocap stream benchmark: skeleton pose sample (25 keypoints, 15 joints, 13 bones), loopback,\n"
              "publish() call -> subscriber take, 2 s per row\n\n");
  const uint32_t domain = testing::loopback_dds_domain();
  for (StreamQos qos : {StreamQos::live, StreamQos::record})
    for (double hz : {60.0, 120.0, 1000.0}) run(hz, qos, domain);
  return 0;
}
