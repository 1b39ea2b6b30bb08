// MJPEG network cameras as the live engine reads them (capture/mjpeg_http_source.h): the multipart parser and the
// JPEG decoder on crafted bytes, then real HTTP servers on loopback (tests/support/mjpeg_server.py) serving real
// pictures of Pose2Sim's take, honest and hostile: corrupt pictures, parts that are not pictures, a part announcing
// 99999999999 bytes, a 404, a refused port, an unknown host, a camera that stalls while it is stopped.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <unistd.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "capture/camera_feed.h"
#include "capture/jpeg_decoder.h"
#include "capture/multipart_reader.h"
#include "core/error.h"
#include "core/log.h"
#include "support/child_process.h"
#include "support/live_helpers.h"
#include "support/mjpeg_camera.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

using Catch::Matchers::ContainsSubstring;
using octocap::internal::MultipartReader;
using testing::Camera;
using testing::serve;

namespace {

const std::string kVideo = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos/cam01.mp4";

std::vector<unsigned char> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

std::string part(const std::string& body, bool with_length, const std::string& delimiter = "--frame") {
  std::string p = delimiter + "\r\nContent-Type: image/jpeg\r\n";
  if (with_length) p += "Content-Length: " + std::to_string(body.size()) + "\r\n";
  return p + "\r\n" + body + "\r\n";
}

// A real picture of the take, JPEG-encoded as a camera would.
std::vector<unsigned char> real_jpeg() {
  cv::VideoCapture cap(kVideo);
  cv::Mat frame;
  REQUIRE(cap.read(frame));
  std::vector<unsigned char> jpeg;
  REQUIRE(cv::imencode(".jpg", frame, jpeg));
  return jpeg;
}

size_t resident_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stoul(line.substr(6)) / 1024;
  return 0;
}

std::unique_ptr<octocap::internal::CameraFeed> feed_for(const std::string& url, octocap::internal::FeedOptions options = {}) {
  return std::make_unique<octocap::internal::CameraFeed>(octocap::internal::parse_camera_spec(url), options, [] {});
}

}  // namespace

TEST_CASE("multipart parts are cut with or without Content-Length; only the newest is kept", "[capture]") {
  MultipartReader reader("frame");
  std::vector<unsigned char> body;
  CHECK_FALSE(reader.take(body));
  const std::string stream = "preamble\r\n" + part("first", true) + part("sec\r\n--nd", true) + part("third", false);
  // Byte by byte: a part is whole only once its last byte came.
  for (size_t i = 0; i < stream.size(); ++i) {
    reader.feed(&stream[i], 1);
    if (reader.take(body)) {
      const std::string got(body.begin(), body.end());
      CHECK((got == "first" || got == "sec\r\n--nd"));
    }
  }
  CHECK_FALSE(reader.take(body));  // "third" has no length: it ends only at the next delimiter
  reader.feed("--frame\r\n", 9);
  REQUIRE(reader.take(body));
  CHECK(body == bytes_of("third"));
  CHECK(reader.skipped() == 0);

  // A reader that fell behind gets the newest part; the ones in between are counted.
  const std::string burst = part("a", true) + part("b", true) + part("c", true);
  reader.feed("\r\n", 2);
  MultipartReader behind("--frame");  // declared with its dashes, as some cameras do
  behind.feed(burst.data(), burst.size());
  REQUIRE(behind.take(body));
  CHECK(body == bytes_of("c"));
  CHECK(behind.skipped() == 2);
}

TEST_CASE("multipart parts larger than any picture are refused at once", "[capture]") {
  MultipartReader reader("frame");
  const std::string huge = "--frame\r\nContent-Type: image/jpeg\r\nContent-Length: 99999999999\r\n\r\n";
  CHECK_THROWS_WITH(reader.feed(huge.data(), huge.size()), ContainsSubstring("99999999999 bytes"));
  MultipartReader negative("frame");
  const std::string bad = "--frame\r\nContent-Length: -5\r\n\r\n";
  CHECK_THROWS_AS(negative.feed(bad.data(), bad.size()), octocap::internal::Error);
  // Without a length, a body that never meets its boundary stops at the cap instead of growing.
  MultipartReader endless("frame");
  const std::string head = "--frame\r\n\r\n";
  endless.feed(head.data(), head.size());
  const std::string chunk(1 << 20, 'x');
  bool refused = false;
  for (int i = 0; i < 80 && !refused; ++i) {
    try {
      endless.feed(chunk.data(), chunk.size());
    } catch (const octocap::internal::Error& e) {
      refused = true;
      CHECK_THAT(e.what(), ContainsSubstring("64 MB"));
      CHECK(i >= 63);
    }
  }
  CHECK(refused);
  // Header lines that never end are not a stream either.
  MultipartReader garbage("frame");
  const std::string noise(100 << 10, 'y');
  CHECK_THROWS_AS(garbage.feed(noise.data(), noise.size()), octocap::internal::Error);
}

TEST_CASE("JPEG pictures decode; corrupt ones, non-pictures and absurd sizes are reported, not smeared", "[capture]") {
  octocap::internal::JpegDecoder decoder;
  const std::vector<unsigned char> jpeg = real_jpeg();
  cv::Mat bgr;
  REQUIRE(decoder.decode(jpeg, bgr));
  const cv::Mat reference = cv::imdecode(jpeg, cv::IMREAD_COLOR);
  CHECK(bgr.size() == reference.size());
  CHECK(cv::norm(bgr, reference, cv::NORM_INF) <= 8);  // both libjpeg; rounding of the colour conversion may differ

  // Bits lost on the wire: the scan's data replaced by noise.
  std::vector<unsigned char> corrupt = jpeg;
  std::mt19937 rng(7);
  for (size_t i = corrupt.size() / 2; i + 2 < corrupt.size(); ++i) corrupt[i] = static_cast<unsigned char>(rng());
  CHECK_FALSE(decoder.decode(corrupt, bgr));
  CHECK_THAT(decoder.why(), ContainsSubstring("corrupt JPEG"));
  CHECK_FALSE(decoder.decode(bytes_of("this is not a picture"), bgr));
  CHECK_THAT(decoder.why(), ContainsSubstring("not a JPEG"));
  // A header claiming 60000x60000 pixels (its SOF0 segment rewritten): refused before any allocation.
  std::vector<unsigned char> giant = jpeg;
  for (size_t i = 0; i + 9 < giant.size(); ++i)
    if (giant[i] == 0xFF && giant[i + 1] == 0xC0) {
      giant[i + 5] = 0xEA, giant[i + 6] = 0x60, giant[i + 7] = 0xEA, giant[i + 8] = 0x60;
      break;
    }
  CHECK_FALSE(decoder.decode(giant, bgr));
  CHECK_THAT(decoder.why(), ContainsSubstring("larger than any camera"));
}

TEST_CASE("an MJPEG camera: corrupt pictures are skipped and counted, the connection kept", "[capture][network]") {
  testing::TempDir dir;
  const Camera cam = serve(dir, "corrupt", {"--every", "3"});
  auto feed = feed_for(cam.url);
  feed->start();
  REQUIRE(testing::wait_until([&] { return feed->status().bad_pictures >= 10; }, 20000));
  const octocap::internal::FeedStatus s = feed->status();
  feed->stop();
  CHECK(s.reconnects == 0);  // FFmpeg's reader reconnected at each one: 47 times in 8 s
  CHECK(s.grabbed >= s.bad_pictures);  // two good pictures for every bad one
  CHECK_THAT(s.last_error, !ContainsSubstring("broke"));
}

TEST_CASE("an MJPEG camera: a part announcing 99999999999 bytes is refused, memory stays flat", "[capture][network]") {
  testing::TempDir dir;
  const Camera cam = serve(dir, "huge-part");
  const size_t before = resident_mb();
  auto feed = feed_for(cam.url);
  feed->start();  // the headers are fine: the camera opens
  REQUIRE(testing::wait_until([&] { return feed->status().reconnects >= 3; }, 20000));
  const size_t after = resident_mb();
  const octocap::internal::FeedStatus s = feed->status();
  feed->stop();
  CHECK_THAT(s.last_error, ContainsSubstring("99999999999 bytes"));
  CHECK(s.grabbed == 0);
  CHECK(after < before + 100);  // FFmpeg's reader took up to 0.75 GB per such camera
}

TEST_CASE("an MJPEG camera whose parts are not pictures says so; unopenable ones give the reason", "[capture][network]") {
  testing::TempDir dir;
  const Camera text = serve(dir, "not-jpeg");
  auto feed = feed_for(text.url);
  feed->start();
  REQUIRE(testing::wait_until([&] { return !feed->status().last_error.empty(); }, 20000));
  const octocap::internal::FeedStatus s = feed->status();
  feed->stop();
  CHECK(s.grabbed == 0);
  CHECK(s.bad_pictures >= 30);
  CHECK_THAT(s.last_error, ContainsSubstring("30 pictures in a row") && ContainsSubstring("not a JPEG picture"));

  octocap::internal::FeedOptions quick;
  quick.source.open_timeout_ms = 1000;
  const Camera missing = serve(dir, "not-found");
  const Camera silent = serve(dir, "silent");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {missing.url, "404"},
      {"http://127.0.0.1:9/cam.mjpg", "Couldn't connect"},
      {"http://no-such-camera.invalid/cam.mjpg", "resolve host"},
      {silent.url, "no answer in 1.0 s"}};
  for (const auto& [url, reason] : cases) {
    auto f = feed_for(url, quick);
    try {
      f->start();
      FAIL("opened " << url);
    } catch (const octocap::internal::Error& e) {
      CHECK(e.code() == octocap::internal::Errc::io);
      CHECK_THAT(e.what(), ContainsSubstring(url) && ContainsSubstring(reason));
    }
  }
}

TEST_CASE("an MJPEG camera: pictures in order, and a stop while it stalls ends the read at once", "[capture][network]") {
  testing::TempDir dir;
  const Camera cam = serve(dir, "stall", {"--parts", "20"});
  octocap::internal::FeedOptions patient;
  patient.source.read_timeout_ms = 20000;  // FFmpeg's reader would sit in its read this long
  auto feed = feed_for(cam.url, patient);
  feed->start();
  REQUIRE(testing::wait_until([&] { return feed->status().grabbed >= 20; }, 20000));
  octocap::internal::CapturedFrame frame;
  const octocap::internal::Candidate newest = feed->candidate(0);
  REQUIRE(feed->take(newest.newest.sequence, frame));
  CHECK(frame.width == 272);
  CHECK(frame.height == 480);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // now inside a read that waits for a 21st part
  const auto t0 = std::chrono::steady_clock::now();
  feed->stop();
  const double stop_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(stop_s < 2.0);  // not a speed figure: a stop that waited for the read would take 20 s
  CHECK(feed->status().state == octocap::internal::FeedState::stopped);
  CHECK(feed->status().last_error.empty());  // the stop is not the camera's error
}

TEST_CASE("an HTTP camera that is not MJPEG (a video file served over HTTP) is read by FFmpeg as before",
          "[capture][network]") {
  testing::TempDir dir;
  const testing::Run r = testing::run_command("ffmpeg -loglevel error -y -i " + kVideo +
                                              " -frames:v 30 -vf scale=272:480 -c:v mpeg4 -an " + dir.file("take.avi"));
  INFO(r.output);
  REQUIRE(r.status == 0);
  // Python's file server on a free port, which it writes down for the test.
  const std::string port_file = dir.file("port");
  const std::string script =
      "import functools, http.server, os, sys\n"
      "class Quiet(http.server.SimpleHTTPRequestHandler):\n"
      "    def log_message(self, *args): pass\n"
      "h = functools.partial(Quiet, directory=sys.argv[1])\n"
      "s = http.server.ThreadingHTTPServer(('127.0.0.1', 0), h)\n"
      "open(sys.argv[2] + '.tmp', 'w').write(str(s.server_address[1])); os.replace(sys.argv[2] + '.tmp', sys.argv[2])\n"
      "s.serve_forever()\n";
  testing::ChildProcess server({"/usr/bin/python3", "-c", script, dir.path().string(), port_file});
  const int port = testing::port_written_to(port_file);
  auto feed = feed_for("http://127.0.0.1:" + std::to_string(port) + "/take.avi");
  feed->start();
  CHECK(testing::wait_until([&] { return feed->status().grabbed >= 10; }, 20000));
  CHECK(feed->status().bad_pictures == 0);
  feed->stop();
}

TEST_CASE("a picture-folder camera skips an unreadable picture, names it, and plays the rest in time", "[capture]") {
  testing::TempDir dir;
  const testing::Run r = testing::run_command("ffmpeg -loglevel error -y -i " + kVideo +
                                              " -frames:v 12 -vf scale=136:240 " + dir.file("f%03d.jpg"));
  INFO(r.output);
  REQUIRE(r.status == 0);
  dir.write("f005.jpg", "this is text, not a picture");
  std::vector<std::string> warnings;
  std::mutex m;
  octocap::internal::set_log_sink([&](octocap::internal::LogLevel level, const char* message) {
    const std::lock_guard<std::mutex> lock(m);
    if (level == octocap::internal::LogLevel::warning) warnings.push_back(message);
  }, octocap::internal::LogLevel::warning);
  octocap::internal::FeedOptions options;
  options.pace_files = false;
  auto feed = feed_for(dir.path().string(), options);
  feed->start();
  REQUIRE(testing::wait_until([&] { return feed->done(); }, 20000));
  // The last picture (the 12th file) keeps its place in time: the bad file was a gap, not a shift.
  octocap::internal::CapturedFrame last;
  REQUIRE(feed->take(feed->candidate(0).newest.sequence, last));
  CHECK(last.stream_us == 11 * 1000000 / 30);
  const octocap::internal::FeedStatus s = feed->status();
  feed->stop();
  octocap::internal::set_log_sink(nullptr, octocap::internal::LogLevel::warning);
  CHECK(s.state == octocap::internal::FeedState::ended);  // played to its end, not stopped at the bad file
  CHECK(s.grabbed == 11);
  CHECK(s.bad_pictures == 1);
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], ContainsSubstring("f005.jpg"));
}
