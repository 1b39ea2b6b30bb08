// Camera passwords never shown: every message the library gives and the command line prints has a URL's password
// replaced by ***, and a password can come from the environment so that `ps` shows none. Real servers on loopback:
// an MJPEG camera whose pictures the engine refuses naming the camera's URL, and a refused camera whose open error
// names its.
#include <catch2/catch_test_macros.hpp>

#include <cstdlib>
#include <string>

#include "octocap/octocap.h"
#include "support/mjpeg_camera.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

namespace {

const std::string kSecret = "S3cretPw";

// octocap live on the sample's five cameras, all `url` (a threaded server serves each its own connection).
testing::Run live_with(const std::string& url, const std::string& env = "") {
  std::string cmd = env + std::string(OCTOCAP_CLI_PATH) + " live --calibration " + OCTOCAP_SOURCE_DIR +
                    "/data/sample/calibration.toml --duration 3";
  for (int c = 0; c < 5; ++c) cmd += " --camera '" + url + "'";
  return testing::run_command(cmd);
}

}  // namespace

TEST_CASE("secrets: a URL's password is replaced by *** and nothing else changes") {
  CHECK(std::string(octocap_redact_credentials("rtsp://admin:S3cret@10.0.0.5:554/x")) == "rtsp://admin:***@10.0.0.5:554/x");
  CHECK(std::string(octocap_redact_credentials("camera 'http://u:p%40ss@host/cam.mjpg': cannot be opened")) ==
        "camera 'http://u:***@host/cam.mjpg': cannot be opened");
  CHECK(std::string(octocap_redact_credentials("a rtsp://a:b@h/x and http://c:d@i?q=1 too")) ==
        "a rtsp://a:***@h/x and http://c:***@i?q=1 too");
  // No password, no URL, a user alone, an '@' in the path: unchanged.
  for (const char* same : {"rtsp://10.0.0.5/x", "camera 2 of 4", "rtsp://admin@host/x", "http://host/a@b:c",
                           "dds://nodeA/cam01", "", "://", "x://@"})
    CHECK(std::string(octocap_redact_credentials(same)) == same);
  CHECK(std::string(octocap_redact_credentials(nullptr)).empty());
}

TEST_CASE("secrets: octocap live never prints a camera's password, in warnings, errors or the final table",
          "[live][secrets]") {
  testing::TempDir dir;
  testing::Camera corrupt = testing::serve(dir, "corrupt", {"--every", "3"});
  const std::string host = corrupt.url.substr(std::string("http://").size());
  const testing::Run r = live_with("http://admin:" + kSecret + "@" + host);
  INFO(r.output);
  CHECK(r.output.find(kSecret) == std::string::npos);
  // Its pictures reached the engine, which stops at their size (the sample is calibrated for other pictures), naming
  // the camera: the message that would have carried the password.
  CHECK(r.output.find("camera 'http://admin:***@" + host + "': its") != std::string::npos);

  SECTION("a camera that refuses: its open error names it, without the password") {
    const testing::Run refused = live_with("http://admin:" + kSecret + "@127.0.0.1:1/cam");
    INFO(refused.output);
    CHECK(refused.status != 0);
    CHECK(refused.output.find(kSecret) == std::string::npos);
    CHECK(refused.output.find("camera 'http://admin:***@127.0.0.1:1/cam': cannot be opened") != std::string::npos);
  }
  SECTION("a password from the environment: ${NAME} in the spec, so that ps shows none") {
    const testing::Run e = live_with("http://admin:${OCTOCAP_TEST_CAMERA_PASSWORD}@" + host,
                                     "OCTOCAP_TEST_CAMERA_PASSWORD=" + kSecret + " ");
    INFO(e.output);
    CHECK(e.output.find(kSecret) == std::string::npos);
    CHECK(e.output.find("camera 'http://admin:***@" + host + "': its") != std::string::npos);  // reached, expanded
    const testing::Run unset = live_with("http://admin:${OCTOCAP_TEST_UNSET_PASSWORD}@127.0.0.1:1/x");
    INFO(unset.output);
    CHECK(unset.status != 0);
    CHECK(unset.output.find("${OCTOCAP_TEST_UNSET_PASSWORD}, which the environment does not set") != std::string::npos);
  }
}
