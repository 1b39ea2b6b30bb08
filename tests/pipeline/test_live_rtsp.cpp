// Four real IP cameras: GStreamer's RTSP server on loopback (tests/support/rtsp_server.py, one process per camera)
// plays Pose2Sim's four real views as H.264 streams at their 60 fps, looped. The live engine solves them as the
// offline solve of the same streams does; one camera's server is killed mid-run and brought back: the engine goes on
// with three views, reconnects, and says so. Behaviour is asserted, never wall-clock speed.
#include <catch2/catch_test_macros.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/videoio.hpp>

#include "octocap/octocap.hpp"
#include "support/child_process.h"
#include "support/live_helpers.h"

namespace fs = std::filesystem;
using namespace testing;

namespace {

const std::string kServer = std::string(OCTOCAP_SOURCE_DIR) + "/tests/support/rtsp_server.py";

// The 544x960 sub-streams: four full-size 60 fps streams alone take most of two cores to decode.
std::string stream_file(int c) { return kStreams + "cam0" + std::to_string(c + 1) + "_960.h264"; }

// How well frames solve: the median reprojection error of solved keypoints, and how often each keypoint is solved in
// sets with a person whom all four views saw (sets without a camera solve fewer, by design).
struct Accuracy {
  static constexpr size_t kKeypoints = 17;
  std::vector<double> reprojection;
  size_t frames = 0, with_person = 0, all_views = 0;
  size_t views[5] = {0, 0, 0, 0, 0};
  std::vector<size_t> solved = std::vector<size_t>(kKeypoints, 0);  // per keypoint
  void add(const octocap::Frame& f) {
    ++frames;
    if (f.person_count() == 0) return;
    ++with_person;
    const uint32_t v = f.person(0).views_with_person;
    ++views[std::min<uint32_t>(4, v)];
    if (v < 4) return;
    ++all_views;
    const auto keypoints = f.keypoints3d(0);
    for (size_t k = 0; k < keypoints.size() && k < kKeypoints; ++k)
      if (keypoints[k].valid) ++solved[k], reprojection.push_back(keypoints[k].reprojection_error_px);
  }
  double rate(size_t k) const { return all_views ? static_cast<double>(solved[k]) / all_views : 0; }
  // Keypoints solved per frame, counting only `which` (all when empty).
  double per_frame(const std::vector<size_t>& which = {}) const {
    double sum = 0;
    for (size_t k = 0; k < kKeypoints; ++k)
      if (which.empty() || std::count(which.begin(), which.end(), k)) sum += rate(k);
    return sum;
  }
};

// The offline answer: every frame of the same four streams, decoded in step, through one session.
Accuracy offline(const octocap::Calibration& calib) {
  std::vector<cv::VideoCapture> caps;
  for (int c = 0; c < 4; ++c) caps.emplace_back(stream_file(c), cv::CAP_FFMPEG);
  octocap::Session session(coco_session(), calib);
  session.set_detector(lightning());
  Accuracy a;
  std::vector<cv::Mat> images(4);
  for (int64_t f = 0;; ++f) {
    std::vector<octocap_image_t> views;
    for (int c = 0; c < 4; ++c) {
      if (!caps[c].read(images[c])) return a;
      octocap_image_t im{};
      im.pixels = images[c].data;
      im.width = static_cast<uint32_t>(images[c].cols);
      im.height = static_cast<uint32_t>(images[c].rows);
      im.stride_bytes = static_cast<uint32_t>(images[c].step[0]);
      im.format = OCTOCAP_PIXELS_BGR8;
      views.push_back(im);
    }
    session.solve_images(views.data(), 4, f * 16667);
    a.add(session.frame());
  }
}

}  // namespace

TEST_CASE("live: four RTSP cameras on loopback solve as offline; one killed and restarted is reconnected",
          "[live][rtsp][real][serial]") {
  REQUIRE(fs::exists("/usr/bin/python3"));  // Debian's, with python3-gi (scripts/install-deps.sh)
  for (int c = 0; c < 4; ++c) REQUIRE(fs::exists(stream_file(c)));
  const int base_port = free_port_run(4);
  REQUIRE(base_port > 0);
  auto url = [&](int c) { return "rtsp://127.0.0.1:" + std::to_string(base_port + c) + "/cam"; };
  auto serve = [&](int c) {
    return std::make_unique<ChildProcess>(std::vector<std::string>{
        "/usr/bin/python3", kServer, "--port", std::to_string(base_port + c), "/cam=" + stream_file(c)});
  };
  std::vector<std::unique_ptr<ChildProcess>> servers;
  for (int c = 0; c < 4; ++c) servers.push_back(serve(c));

  const octocap::Calibration calib = octocap::Calibration::load(kDemo + "/calibration/Calib_qualisys.toml");
  const Accuracy reference = offline(calib);
  REQUIRE(reference.frames == 100);

  octocap_live_config_t cfg;
  octocap_live_config_init(&cfg);
  cfg.read_timeout_ms = 1500;
  cfg.reconnect_max_ms = 500;
  std::vector<std::string> cameras;
  for (int c = 0; c < 4; ++c) cameras.push_back(url(c));
  octocap::Live live(cfg, coco_session(), calib, cameras);
  live.set_detector(lightning());
  for (int c = 0; c < 4; ++c) REQUIRE(port_accepts(base_port + c, 30000));  // a cold machine starts Python slowly
  live.start();
  for (int c = 0; c < 4; ++c) CHECK(live.camera(static_cast<uint32_t>(c)).nominal_fps > 50);  // they say 60

  // Every camera streaming (each starts at its stream's next key frame: up to half a second), then at least 60
  // frames solved, as accurate as offline.
  REQUIRE(wait_until([&] {
    for (uint32_t c = 0; c < 4; ++c)
      if (live.camera(c).grabbed < 30) return false;
    return true;
  }, 20000));
  // Capture times from the streams' own clocks (RTP), not from when a busy host decoded each picture: before that,
  // sets may pair pictures of different instants, by design, and that is not what the accuracy below is about.
  REQUIRE(wait_until([&] {
    for (uint32_t c = 0; c < 4; ++c)
      if (!live.camera(c).stream_clock) return false;
    return true;
  }, 20000));
  while (live.take(0)) {
  }
  Accuracy all_four;
  while (all_four.all_views < 60)
    if (std::optional<octocap::Frame> f = live.take(10000)) all_four.add(*f);
    else FAIL("no frame in 10 s");
  // The keypoints offline solves in nine frames of ten: the others sit at the detector's confidence threshold (which of
  // them do differs with the CPU's kernels: AVX2 solves 16.9 of 17, AVX-512 15.2), so whether a live set, with its
  // own crops, solves them is a coin's throw that says nothing of the live engine.
  std::vector<size_t> steady;
  for (size_t k = 0; k < Accuracy::kKeypoints; ++k)
    if (reference.rate(k) >= 0.9) steady.push_back(k);
  INFO("offline: median reprojection " << median_of(reference.reprojection) << " px, " << reference.per_frame()
                                       << " keypoints per frame, " << steady.size() << " solved steadily ("
                                       << reference.per_frame(steady) << " per frame); live: "
                                       << median_of(all_four.reprojection) << " px, " << all_four.per_frame() << ", "
                                       << all_four.per_frame(steady) << " of the steady ones; sets with a person in "
                                       << "2/3/4 views " << all_four.views[2] << "/" << all_four.views[3] << "/"
                                       << all_four.views[4] << "; per keypoint offline/live: " << [&] {
                                         std::string r;
                                         for (size_t k = 0; k < Accuracy::kKeypoints; ++k)
                                           r += std::to_string(k) + " " + std::to_string(reference.rate(k)).substr(0, 4) +
                                                "/" + std::to_string(all_four.rate(k)).substr(0, 4) + ", ";
                                         return r;
                                       }());
  CHECK(steady.size() >= 12);  // the limbs at least
  CHECK(all_four.with_person >= 0.75 * all_four.frames);  // a set of one view solves nobody: under load, a few
  CHECK(all_four.all_views >= 0.6 * all_four.with_person);  // most sets whole, though decoding shares two cores
  CHECK(median_of(all_four.reprojection) <= 1.2 * median_of(reference.reprojection) + 0.5);
  // Within a tenth of offline (measured: 0.98-1.0): live pictures are up to half a frame apart across views, and only
  // every fifth or so is detected (the crops follow a person who moved further; bench_detect --crop-gap: no loss).
  CHECK(all_four.per_frame(steady) >= 0.9 * reference.per_frame(steady));

  // Camera 2's server dies: the engine goes on with three views while it reconnects.
  servers[1]->kill_now();
  servers[1]->wait();
  REQUIRE(wait_until([&] { return live.camera(1).state == OCTOCAP_CAMERA_RECONNECTING; }, 10000));
  CHECK(frames_seen_by(live, 3, 10, 200) == 10);
  CHECK(live.camera(0).state == OCTOCAP_CAMERA_STREAMING);
  CHECK(live.camera(2).state == OCTOCAP_CAMERA_STREAMING);

  // It comes back: reconnected, counted, four views again.
  servers[1] = serve(1);
  REQUIRE(wait_until([&] { return live.camera(1).state == OCTOCAP_CAMERA_STREAMING; }, 20000));
  CHECK(live.camera(1).reconnects >= 1);
  CHECK(frames_seen_by(live, 4, 10, 300) == 10);
  const octocap_live_stats_t stats = live.stats();
  CHECK(stats.sets_incomplete >= 10);
  CHECK(stats.latency_p99_ms >= stats.latency_p50_ms);
  for (uint32_t c = 0; c < 4; ++c) {
    const octocap_camera_status_t cam = live.camera(c);
    CHECK(cam.used + cam.dropped <= cam.grabbed);
    if (c != 1) CHECK(cam.reconnects == 0);
  }
  live.stop();
}
