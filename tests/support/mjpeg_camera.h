// An MJPEG camera for tests: tests/support/mjpeg_server.py on loopback, honest or hostile (its --mode), serving
// real pictures of Pose2Sim's take (cam01, 272x480, made once per test folder).
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "child_process.h"
#include "live_helpers.h"
#include "run_command.h"
#include "temp_dir.h"

namespace testing {

struct Camera {
  std::unique_ptr<ChildProcess> server;
  std::string url;
};

// The port a test server listened on, from the file it writes once it accepts (a free port it chose itself, so tests
// running at once never race for one).
inline int port_written_to(const std::string& port_file) {
  REQUIRE(wait_until([&] { return std::filesystem::exists(port_file); }, 20000));
  int port = 0;
  std::ifstream(port_file) >> port;
  REQUIRE(port > 0);
  return port;
}

inline Camera serve(const TempDir& dir, const std::string& mode, std::vector<std::string> extra = {}) {
  static int served = 0;
  const std::string video = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos/cam01.mp4";
  const std::string pictures = dir.file("pictures");
  if (!std::filesystem::exists(pictures)) {
    std::filesystem::create_directories(pictures);
    const Run r = run_command("ffmpeg -loglevel error -y -i " + video + " -frames:v 60 -vf scale=272:480 -q:v 4 " +
                              pictures + "/%04d.jpg");
    INFO(r.output);
    REQUIRE(r.status == 0);
  }
  const std::string port_file = dir.file("port" + std::to_string(++served));
  std::vector<std::string> argv = {"/usr/bin/python3", std::string(OCTOCAP_SOURCE_DIR) + "/tests/support/mjpeg_server.py",
                                   "--port-file", port_file, "--pictures", pictures, "--mode", mode};
  argv.insert(argv.end(), extra.begin(), extra.end());
  auto server = std::make_unique<ChildProcess>(argv);
  const int port = port_written_to(port_file);
  return {std::move(server), "http://127.0.0.1:" + std::to_string(port) + "/cam.mjpg"};
}

}  // namespace testing
