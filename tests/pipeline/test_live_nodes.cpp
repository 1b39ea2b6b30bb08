// More cameras than one machine detects: two capture-node processes (octocap detect --live --publish-keypoints), each
// with two real IP cameras (GStreamer's RTSP server on loopback playing Pose2Sim's views), publish 2D keypoints over
// loopback DDS; this process is the hub, a live capture whose cameras are dds://NODE/CAMERA. One node is killed and
// restarted: the hub goes on with the other's two views, reconnects, and says so. Behaviour is asserted, not speed.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "octocap/octocap.hpp"
#include "support/child_process.h"
#include "support/live_helpers.h"
#include "support/loopback_dds.h"
#include "support/run_command.h"

using Catch::Matchers::ContainsSubstring;
using namespace testing;

namespace {

const std::string kServer = std::string(OCTOCAP_SOURCE_DIR) + "/tests/support/rtsp_server.py";

}  // namespace

TEST_CASE("capture nodes: two node processes publish keypoints, a hub solves them; a node killed and restarted",
          "[live][nodes][dds][real][serial]") {
  const uint32_t domain = loopback_dds_domain();  // the children inherit the loopback configuration
  const int base_port = free_port_run(4);
  REQUIRE(base_port > 0);
  auto url = [&](int c) { return "rtsp://127.0.0.1:" + std::to_string(base_port + c) + "/cam"; };
  std::vector<std::unique_ptr<ChildProcess>> servers;
  for (int c = 0; c < 4; ++c)
    servers.push_back(std::make_unique<ChildProcess>(std::vector<std::string>{
        "/usr/bin/python3", kServer, "--port", std::to_string(base_port + c),
        "/cam=" + kStreams + "cam0" + std::to_string(c + 1) + "_960.h264"}));
  for (int c = 0; c < 4; ++c) REQUIRE(port_accepts(base_port + c, 30000));  // the cameras are on before the nodes
  // Node A has cameras 1 and 2, node B cameras 3 and 4; both detect at the same 5 ticks a second.
  auto node = [&](const std::string& name, int first) {
    return std::make_unique<ChildProcess>(std::vector<std::string>{
        OCTOCAP_CLI_PATH, "detect", "--live", "--publish-keypoints", "--node", name, "--domain", std::to_string(domain),
        "--camera", url(first), "--camera", url(first + 1), "--camera-name", "cam0" + std::to_string(first + 1),
        "--camera-name", "cam0" + std::to_string(first + 2), "--model", "movenet-lightning", "--detect-rate", "5",
        "--quiet"});
  };
  auto node_a = node("nodeA", 0);
  auto node_b = node("nodeB", 2);

  const octocap::Calibration calib = octocap::Calibration::load(kDemo + "/calibration/Calib_qualisys.toml");
  const std::vector<std::string> remote = {"dds://nodeA/cam01", "dds://nodeA/cam02", "dds://nodeB/cam03",
                                           "dds://nodeB/cam04"};
  octocap_live_config_t cfg;
  octocap_live_config_init(&cfg);
  cfg.remote_domain_id = domain;
  cfg.open_timeout_ms = 30000;  // the nodes load their models and connect to their cameras first
  cfg.read_timeout_ms = 1500;
  octocap::Live hub(cfg, coco_session(), calib, remote);  // no detector: the nodes detect
  hub.start();
  REQUIRE(hub.take(30000));
  let_stream_clocks_settle();  // the nodes' cameras (twice: on two loaded cores the nodes start them unevenly)
  let_stream_clocks_settle();
  while (hub.take(0)) {
  }

  // Whole sets: all four views of one instant, solved as well as the take solves offline.
  std::vector<double> reprojection;
  size_t frames = 0, whole = 0, solved = 0;
  while (whole < 20) {
    std::optional<octocap::Frame> f = hub.take(10000);
    REQUIRE(f);
    INFO("frames " << frames << ", whole " << whole << "; views of the last: "
                   << (f->person_count() ? f->person(0).views_with_person : 0));
    REQUIRE(frames < 200);  // at 5 sets a second: 40 s (a view that never finds the person again: fails, not hangs)
    ++frames;
    if (f->person_count() == 0 || f->person(0).views_with_person < 4) continue;
    ++whole;
    for (const octocap_joint_t& k : f->keypoints3d(0))
      if (k.valid) ++solved, reprojection.push_back(k.reprojection_error_px);
  }
  INFO("frames " << frames << ", whole " << whole << ", keypoints per whole frame " << solved / 20.0
                 << ", median reprojection " << median_of(reprojection) << " px");
  CHECK(whole >= 0.6 * frames);
  // Offline the take solves 16.9 of 17; here views of two processes meet on capture times, each within half a frame
  // of the tick (measured 13.9-16.9 on two loaded cores: a wrist 8 ms apart in two views is dropped, not guessed).
  CHECK(solved >= 0.8 * 17 * whole);
  CHECK(median_of(reprojection) <= 10.7);  // Pose2Sim's own median on this take
  for (uint32_t c = 0; c < 4; ++c) {
    const octocap_camera_status_t cam = hub.camera(c);
    CHECK(cam.state == OCTOCAP_CAMERA_STREAMING);
    CHECK(cam.nominal_fps > 50);            // the node passes on what its camera says (60)
    CHECK(std::abs(cam.clock_offset_ms) < 50);  // one host, one clock: transit only
  }

  // The hub's command line, on the same nodes.
  std::string cameras;
  for (const std::string& r : remote) cameras += " --camera " + r;
  const Run cli = run_command(std::string(OCTOCAP_CLI_PATH) + " live --calibration " + kDemo +
                              "/calibration/Calib_qualisys.toml" + cameras + " --domain " + std::to_string(domain) +
                              " --duration 3 --quiet");
  INFO(cli.output);
  CHECK(cli.status == 0);
  CHECK_THAT(cli.output, ContainsSubstring("dds://nodeB/cam04, clock offset"));

  // Node B dies: its cameras fall silent and are awaited again; node A's two views go on.
  node_b->kill_now();
  node_b->wait();
  REQUIRE(wait_until([&] { return hub.camera(2).state == OCTOCAP_CAMERA_RECONNECTING; }, 10000));
  CHECK(frames_seen_by(hub, 2, 5, 100) == 5);
  CHECK(hub.camera(0).state == OCTOCAP_CAMERA_STREAMING);

  // It comes back: reconnected, counted, four views again.
  node_b = node("nodeB", 2);
  REQUIRE(wait_until([&] { return hub.camera(3).state == OCTOCAP_CAMERA_STREAMING; }, 30000));
  CHECK(hub.camera(2).reconnects + hub.camera(3).reconnects >= 1);
  CHECK(frames_seen_by(hub, 4, 5, 100) == 5);
  CHECK(hub.camera(0).reconnects == 0);
  hub.stop();

  // A remote camera nobody publishes is a clear error naming it; a malformed one too.
  octocap_live_config_t quick = cfg;
  quick.open_timeout_ms = 500;
  octocap::Live missing(quick, coco_session(), calib,
                        {"dds://nodeA/cam01", "dds://nodeA/cam02", "dds://nodeB/cam03", "dds://nodeZ/cam09"});
  try {
    missing.start();
    FAIL("started without node Z");
  } catch (const octocap::Error& e) {
    CHECK_THAT(e.what(), ContainsSubstring("dds://nodeZ/cam09"));
  }
  CHECK_THROWS_WITH(octocap::Live(quick, coco_session(), calib, {"dds://nodeA", "x", "y", "z"}),
                    ContainsSubstring("dds://NODE/CAMERA"));
}

TEST_CASE("capture nodes: misuse is a clear error, never a crash", "[live][nodes][misuse]") {
  octocap_node_config_t cfg;
  octocap_node_config_init(&cfg);
  CHECK(cfg.struct_size == sizeof cfg);
  CHECK(std::string(cfg.name) == "node1");
  CHECK(cfg.detect_rate_hz == 0);
  const std::string video = kVideos + "cam01.mp4";
  const char* one[] = {video.c_str()};
  const char* two[] = {video.c_str(), video.c_str()};
  const char* same[] = {"a", "a"};
  octocap_node_t* node = nullptr;
  CHECK(octocap_node_create(nullptr, one, nullptr, 1, &node) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_node_create(&cfg, one, nullptr, 0, &node) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_node_create(&cfg, two, same, 2, &node) == OCTOCAP_ERROR_INVALID_ARGUMENT);  // two cameras "a"
  const char* remote[] = {"dds://other/cam01"};
  CHECK(octocap_node_create(&cfg, remote, nullptr, 1, &node) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  const char* missing[] = {"/nonexistent/clip.mp4"};
  CHECK(octocap_node_create(&cfg, missing, nullptr, 1, &node) == OCTOCAP_ERROR_IO);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("/nonexistent/clip.mp4"));
  octocap_node_config_t bad = cfg;
  std::snprintf(bad.name, sizeof bad.name, "%s", "a/b");
  CHECK(octocap_node_create(&bad, one, nullptr, 1, &node) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  bad = cfg;
  bad.detect_rate_hz = NAN;
  CHECK(octocap_node_create(&bad, one, nullptr, 1, &node) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  bad = cfg;
  bad.struct_size = 12;
  CHECK(octocap_node_create(&bad, one, nullptr, 1, &node) == OCTOCAP_ERROR_STRUCT_SIZE);
  CHECK(node == nullptr);
  CHECK(octocap_node_start(nullptr) == OCTOCAP_ERROR_INVALID_HANDLE);
  CHECK(octocap_node_stop(nullptr) == OCTOCAP_ERROR_INVALID_HANDLE);
  octocap_node_destroy(nullptr);

  // A real one: stop before start is fine, a camera index out of range is refused, start twice is refused.
  loopback_dds_domain();
  REQUIRE(octocap_node_create(&cfg, one, nullptr, 1, &node) == OCTOCAP_OK);
  CHECK(octocap_node_stop(node) == OCTOCAP_OK);
  octocap_camera_status_t cam{};
  cam.struct_size = sizeof cam;
  CHECK(octocap_node_get_camera_status(node, 1, &cam) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  REQUIRE(octocap_node_get_camera_status(node, 0, &cam) == OCTOCAP_OK);
  CHECK(std::string(cam.name) == "cam01");
  octocap_detector_config_t det = lightning();
  REQUIRE(octocap_node_set_detector(node, &det) == OCTOCAP_OK);
  REQUIRE(octocap_node_start(node) == OCTOCAP_OK);
  CHECK(octocap_node_start(node) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_node_set_detector(node, &det) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_node_destroy(node);  // while running
  CHECK(octocap_node_start(node) == OCTOCAP_ERROR_INVALID_HANDLE);  // dangling
}
