// Live capture benchmark (not a test): the engine end to end on real footage delivered as cameras deliver it.
//   files:   Pose2Sim's 4 real videos (1088x1920, 60 fps) played as cameras at their own rate;
//   network: the same views as MJPEG over HTTP on loopback (ffmpeg servers, 272x480, 60 fps), 2 and 4 cameras;
//   rtsp:    the same views as H.264 IP cameras (GStreamer's RTSP server on loopback, tests/support/rtsp_server.py),
//            544x960 sub-streams for 2, 4 and 8 cameras (8: the four views twice), and the 1088x1920 main streams.
// Per row: solved frame sets per second, sets without every camera, per-stage means (image collection = waiting for
// the set, 2D detection, 3D + rig), grab-to-frame latency p50 / p99, pictures dropped (bounded mailboxes at work).
// `--soak SECONDS`: instead, four RTSP sub-streams for that long, a line every 30 s (rate, latency, whole sets, the
// process's resident memory): latency and memory stay flat when every hand-over is bounded.
// `--rtsp`: only the RTSP rows.
// `--webcams [--busy]`: four webcam-class MJPEG cameras (544x960 and 720x1280 at 30 frames/s, ffmpeg servers on
// loopback), the defaults (the rate governor) against --quality max: sets/s, latency, keypoint cells solved, the rung
// the governor ended on; `--busy` keeps one core busy with another process meanwhile.
#include <unistd.h>

#include <cstring>
#include <fstream>

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "child_process.h"
#include "octocap/octocap.hpp"

namespace {

const std::string kRoot = OCTOCAP_SOURCE_DIR;
const std::string kVideos = kRoot + "/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos/";
const std::string kLab = kRoot + "/.cache/pose2sim-0.4.15/Demo/calibration/Calib_qualisys.toml";

// views_per_frame: detection scheduling (0: every view detected every set).
void row(const char* what, const octocap::Calibration& calib, const std::vector<std::string>& cameras,
         const char* model, double seconds, uint32_t views_per_frame = 0) {
  octocap_live_config_t cfg;
  octocap_live_config_init(&cfg);
  octocap_session_config_t s;
  octocap_session_config_init(&s);
  s.layout = OCTOCAP_LAYOUT_COCO_17;
  octocap::Live live(cfg, s, calib, cameras);
  octocap_detector_config_t d;
  octocap_detector_config_init(&d);
  std::snprintf(d.model, sizeof d.model, "%s", model);
  d.views_per_frame = views_per_frame;
  live.set_detector(d);
  live.start();
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds) {
    if (!live.take(500) && live.stats().finished) break;
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  live.stop();
  const octocap_live_stats_t st = live.stats();
  uint64_t grabbed = 0, dropped = 0;
  for (uint32_t c = 0; c < st.camera_count; ++c) {
    grabbed += live.camera(c).grabbed;
    dropped += live.camera(c).dropped;
  }
  char label[96];
  std::snprintf(label, sizeof label, views_per_frame ? "%s, %u detected a set" : "%s", model, views_per_frame);
  std::printf("| %-34s | %-17s | %5.1f | %4.0f %% | %6.1f | %6.1f | %5.2f | %5.0f / %5.0f | %3.0f %% |\n", what, label,
              static_cast<double>(st.frame_sets) / elapsed,
              st.frame_sets ? 100.0 * static_cast<double>(st.sets_incomplete) / static_cast<double>(st.frame_sets) : 0.0,
              st.capture_ms, st.detect_ms, st.solve_ms, st.latency_p50_ms, st.latency_p99_ms,
              grabbed ? 100.0 * static_cast<double>(dropped) / static_cast<double>(grabbed) : 0.0);
}

// One governed (or not) live run of `seconds`: rate, latency, keypoint cells solved of the frames taken, the rung.
void governed_row(const char* what, const octocap::Calibration& calib, const std::vector<std::string>& cameras,
                  octocap_live_quality_t quality, double seconds) {
  octocap_live_config_t cfg;
  octocap_live_config_init(&cfg);
  cfg.quality = quality;
  octocap_session_config_t s;
  octocap_session_config_init(&s);
  s.layout = OCTOCAP_LAYOUT_COCO_17;
  octocap::Live live(cfg, s, calib, cameras);
  octocap_detector_config_t d;
  octocap_detector_config_init(&d);
  live.set_detector(d);
  live.start();
  // The first two seconds: cameras connecting, the governor finding its rung; not what a take is like.
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  while (elapsed() < 2) live.take(100);
  const octocap_live_stats_t before = live.stats();
  uint64_t taken = 0, cells = 0;
  while (elapsed() < 2 + seconds) {
    std::optional<octocap::Frame> f = live.take(500);
    if (!f) continue;
    ++taken;
    if (f->summary().person_count == 0) continue;
    for (const octocap_joint_t& k : f->keypoints3d(0)) cells += k.valid ? 1 : 0;
  }
  const octocap_live_stats_t st = live.stats();
  live.stop();
  char rung[48] = "";
  if (st.quality_rungs > 0) std::snprintf(rung, sizeof rung, " (rung %u of %u)", st.quality_rung + 1, st.quality_rungs);
  std::printf("| %-30s | %-8s | %5.1f | %5.0f / %5.0f | %5.1f %% | %s on %u view%s%s | %u | %5.1f |\n", what,
              quality == OCTOCAP_QUALITY_MAX ? "max" : "governed",
              static_cast<double>(st.frame_sets - before.frame_sets) / seconds, st.latency_p50_ms, st.latency_p99_ms,
              taken ? 100.0 * static_cast<double>(cells) / (17.0 * static_cast<double>(taken)) : 0.0, st.model,
              st.views_detected, st.views_detected == 1 ? "" : "s", rung, st.rung_changes, st.detect_ms);
  std::fflush(stdout);
}

// Four MJPEG cameras at 30 frames/s, `width`x`height`, served by ffmpeg on loopback; the rows of --webcams.
void webcam_rows(const octocap::Calibration& lab, const std::vector<std::string>& files, int width, int height) {
  const std::string tmp = "/tmp/octocap-bench-webcam-" + std::to_string(getpid());
  std::vector<std::string> avis, urls;
  for (int c = 0; c < 4; ++c) {
    avis.push_back(tmp + "-cam" + std::to_string(c) + ".avi");
    const std::string cmd = "ffmpeg -loglevel error -y -i " + files[static_cast<size_t>(c)] + " -vf fps=30,scale=" +
                            std::to_string(width) + ":" + std::to_string(height) + " -c:v mjpeg -q:v 4 -an " + avis.back();
    if (std::system(cmd.c_str()) != 0) {
      std::printf("(ffmpeg failed: no webcam rows)\n");
      return;
    }
    urls.push_back("http://127.0.0.1:" + std::to_string(30510 + c) + "/cam.mjpg");
  }
  const std::string what = "4 MJPEG " + std::to_string(width) + "x" + std::to_string(height) + " @ 30";
  for (octocap_live_quality_t q : {OCTOCAP_QUALITY_GOVERNED, OCTOCAP_QUALITY_MAX}) {
    std::vector<std::unique_ptr<testing::ChildProcess>> servers;  // each ffmpeg serves one client
    for (int c = 0; c < 4; ++c)
      servers.push_back(std::make_unique<testing::ChildProcess>(std::vector<std::string>{
          "/usr/bin/ffmpeg", "-loglevel", "quiet", "-re", "-stream_loop", "-1", "-i", avis[static_cast<size_t>(c)],
          "-c:v", "copy", "-f", "mpjpeg", "-listen", "1", urls[static_cast<size_t>(c)]}));
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    governed_row(what.c_str(), lab, urls, q, 20);
  }
  for (const std::string& avi : avis) std::remove(avi.c_str());
}

double resident_mb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
}

// An RTSP server on loopback with a mount per view, and `count` cameras on it (the four views in turn).
struct RtspRig {
  std::unique_ptr<testing::ChildProcess> server;
  std::unique_ptr<octocap::Calibration> calib;
  std::vector<std::string> urls;
};

RtspRig rtsp_rig(const octocap::Calibration& lab, int count, const std::string& suffix) {
  RtspRig rig;
  const std::string streams = kRoot + "/.cache/rtsp-streams/";
  std::vector<std::string> args = {"/usr/bin/python3", kRoot + "/tests/support/rtsp_server.py", "--port", "30600"};
  for (int c = 1; c <= 4; ++c)
    args.push_back("/cam" + std::to_string(c) + "=" + streams + "cam0" + std::to_string(c) + suffix + ".h264");
  rig.server = std::make_unique<testing::ChildProcess>(args);
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  std::vector<octocap_camera_t> cams;
  for (int c = 0; c < count; ++c) {
    cams.push_back(lab.camera(static_cast<uint32_t>(c % 4)));
    std::snprintf(cams.back().name, sizeof cams.back().name, "cam_%02d", c + 1);
    rig.urls.push_back("rtsp://127.0.0.1:30600/cam" + std::to_string(c % 4 + 1));
  }
  octocap_calibration_t* sub = nullptr;
  octocap::check(octocap_calibration_create(cams.data(), static_cast<uint32_t>(cams.size()), &sub), "cameras");
  rig.calib = std::make_unique<octocap::Calibration>(sub);
  return rig;
}

int soak(const octocap::Calibration& lab, double seconds) {
  RtspRig rig = rtsp_rig(lab, 4, "_960");
  octocap_live_config_t cfg;
  octocap_live_config_init(&cfg);
  octocap_session_config_t s;
  octocap_session_config_init(&s);
  s.layout = OCTOCAP_LAYOUT_COCO_17;
  octocap::Live live(cfg, s, *rig.calib, rig.urls);
  octocap_detector_config_t d;
  octocap_detector_config_init(&d);
  std::snprintf(d.model, sizeof d.model, "%s", "movenet-lightning");
  live.set_detector(d);
  live.start();
  std::printf("# octocap live, 4 RTSP cameras (544x960 @ 60, loopback), movenet-lightning, %.0f s\n\n", seconds);
  std::printf("| time s | sets/s | whole sets | latency p50 / p99 ms | resident MB | reconnects |\n|---|---|---|---|---|---|\n");
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  octocap_live_stats_t before = live.stats();
  double window_start = 0;
  while (elapsed() < seconds) {
    live.take(500);
    if (elapsed() - window_start < 30 && elapsed() < seconds) continue;
    const octocap_live_stats_t now = live.stats();
    const double span = elapsed() - window_start;
    const double sets = static_cast<double>(now.frame_sets - before.frame_sets);
    const double whole = sets - static_cast<double>(now.sets_incomplete - before.sets_incomplete);
    uint64_t reconnects = 0;
    for (uint32_t c = 0; c < now.camera_count; ++c) reconnects += live.camera(c).reconnects;
    std::printf("| %6.0f | %5.1f | %3.0f %% | %5.0f / %5.0f | %6.0f | %llu |\n", elapsed(), sets / span,
                sets > 0 ? 100.0 * whole / sets : 0.0, now.latency_p50_ms, now.latency_p99_ms, resident_mb(),
                static_cast<unsigned long long>(reconnects));
    std::fflush(stdout);
    before = now;
    window_start = elapsed();
  }
  live.stop();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const octocap::Calibration lab = octocap::Calibration::load(kLab);
  if (argc == 3 && std::strcmp(argv[1], "--soak") == 0) return soak(lab, std::atof(argv[2]));
  const bool rtsp_only = argc == 2 && std::strcmp(argv[1], "--rtsp") == 0;
  const bool scheduling = argc == 2 && std::strcmp(argv[1], "--scheduling") == 0;
  const bool webcams = argc >= 2 && std::strcmp(argv[1], "--webcams") == 0;
  const bool busy = webcams && argc == 3 && std::strcmp(argv[2], "--busy") == 0;
  if (argc > 1 && !rtsp_only && !scheduling && !(webcams && (argc == 2 || busy))) {
    std::fprintf(stderr, "usage: octocap_bench_live [--rtsp | --scheduling | --webcams [--busy] | --soak SECONDS]\n");
    return 2;
  }
  if (webcams) {
    std::vector<std::string> files;
    for (int c = 1; c <= 4; ++c) files.push_back(kVideos + "cam0" + std::to_string(c) + ".mp4");
    std::unique_ptr<testing::ChildProcess> burner;
    if (busy) burner = std::make_unique<testing::ChildProcess>(std::vector<std::string>{"/bin/sh", "-c", "while :; do :; done"});
    std::printf("# octocap live, webcam-class cameras, default detector (movenet-thunder)%s, 20 s a row after 2 s\n\n",
                busy ? ", one core kept busy by another process" : "");
    std::printf("| cameras | quality | sets/s | latency p50 / p99 ms | keypoint cells solved | last set | rung changes | detect ms |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    webcam_rows(lab, files, 544, 960);
    webcam_rows(lab, files, 720, 1280);
    return 0;
  }
  std::printf("# octocap live engine (this machine, default threads; the detector decides the rate)\n\n");
  std::printf("| cameras | model | sets/s | incomplete | collect ms | detect ms | 3D+rig ms | latency p50 / p99 ms | dropped |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> files;
  for (int c = 1; c <= 4; ++c) files.push_back(kVideos + "cam0" + std::to_string(c) + ".mp4");
  auto rtsp_row = [&](const char* what, int count, const std::string& suffix) {
    RtspRig rig = rtsp_rig(lab, count, suffix);
    row(what, *rig.calib, rig.urls, "movenet-lightning", 10);
  };
  auto rtsp_rows = [&] {
    rtsp_row("2 RTSP cameras, 544x960 @ 60", 2, "_960");
    rtsp_row("4 RTSP cameras, 544x960 @ 60", 4, "_960");
    rtsp_row("8 RTSP cameras, 544x960 @ 60", 8, "_960");
    rtsp_row("4 RTSP cameras, 1088x1920 @ 60", 4, "");
  };
  if (rtsp_only) {
    rtsp_rows();
    return 0;
  }
  if (scheduling) {  // detection scheduling: views followed by optical flow between their detections
    for (const char* model : {"movenet-thunder", "movenet-lightning"})
      for (uint32_t views : {0u, 2u, 1u}) row("4 video files, 1088x1920 @ 60", lab, files, model, 10, views);
    return 0;
  }
  for (const char* model : {"movenet-lightning", "movenet-thunder"})
    row("4 video files, 1088x1920 @ 60", lab, files, model, 10);

  // The same views as IP cameras: small MJPEG files served in a loop by ffmpeg.
  const std::string tmp = "/tmp/octocap-bench-live-" + std::to_string(getpid());
  std::vector<std::string> avis, urls;
  for (int c = 0; c < 4; ++c) {
    avis.push_back(tmp + "-cam" + std::to_string(c) + ".avi");
    const std::string cmd = "ffmpeg -loglevel error -y -i " + files[c] + " -vf scale=272:480 -c:v mjpeg -q:v 4 -an " + avis[c];
    if (std::system(cmd.c_str()) != 0) {
      std::printf("\n(ffmpeg not found: network rows skipped)\n");
      return 0;
    }
    urls.push_back("http://127.0.0.1:" + std::to_string(30500 + c) + "/cam.mjpg");
  }
  // Each ffmpeg serves one client: a fresh set of servers per row.
  std::vector<std::unique_ptr<testing::ChildProcess>> servers;
  auto serve_all = [&] {
    servers.clear();
    for (int c = 0; c < 4; ++c)
      servers.push_back(std::make_unique<testing::ChildProcess>(std::vector<std::string>{
          "/usr/bin/ffmpeg", "-loglevel", "quiet", "-re", "-stream_loop", "-1", "-i", avis[c], "-c:v", "copy", "-f",
          "mpjpeg", "-listen", "1", urls[c]}));
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  };
  serve_all();
  const octocap_camera_t two_cams[2] = {lab.camera(0), lab.camera(1)};
  octocap_calibration_t* raw = nullptr;
  octocap::check(octocap_calibration_create(two_cams, 2, &raw), "two cameras");
  const octocap::Calibration two(raw);
  row("2 MJPEG/HTTP cameras, 272x480 @ 60", two, {urls[0], urls[1]}, "movenet-lightning", 10);
  serve_all();
  row("4 MJPEG/HTTP cameras, 272x480 @ 60", lab, urls, "movenet-lightning", 10);
  servers.clear();
  for (const std::string& avi : avis) std::remove(avi.c_str());

  rtsp_rows();
  return 0;
}
