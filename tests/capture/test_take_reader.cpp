// Recorded takes through the C ABI (octocap_take_reader_*): the pictures `octocap solve --images` and `octocap
// detect` read. Picture folders whose every pixel says which camera and frame it is, videos written here with a
// known picture per frame, and Pose2Sim's real take checked against OpenCV decoding the same files on its own.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "octocap/octocap.h"
#include "support/temp_dir.h"

using Catch::Matchers::ContainsSubstring;

namespace {

const std::string kRealVideos = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos";

// Camera c's picture of frame f: one flat colour that says both (within a video codec's error).
cv::Scalar mark(int camera, int frame) { return cv::Scalar(20 + 10 * frame, 40 + 60 * camera, 200); }

void write_picture_take(const testing::TempDir& dir, const std::vector<int>& frames_per_camera) {
  for (size_t c = 0; c < frames_per_camera.size(); ++c) {
    const auto folder = dir.path() / ("cam" + std::to_string(c + 1));
    std::filesystem::create_directories(folder);
    for (int f = 0; f < frames_per_camera[c]; ++f) {
      char name[32];
      std::snprintf(name, sizeof name, "%06d.png", f);
      REQUIRE(cv::imwrite((folder / name).string(), cv::Mat(48, 64, CV_8UC3, mark(static_cast<int>(c), f))));
    }
  }
}

// The largest difference between a borrowed image and camera c's mark of frame f.
double off_mark(const octocap_image_t& im, int camera, int frame) {
  REQUIRE(im.pixels != nullptr);
  REQUIRE(im.format == OCTOCAP_PIXELS_BGR8);
  const cv::Mat m(static_cast<int>(im.height), static_cast<int>(im.width), CV_8UC3, const_cast<uint8_t*>(im.pixels),
                  im.stride_bytes);
  cv::Mat diff;
  cv::absdiff(m, cv::Mat(m.size(), CV_8UC3, mark(camera, frame)), diff);
  double worst = 0;
  cv::minMaxLoc(diff.reshape(1), nullptr, &worst);
  return worst;
}

octocap_take_info_t info_of(const octocap_take_reader_t* r) {
  octocap_take_info_t info{};
  info.struct_size = sizeof info;
  REQUIRE(octocap_take_reader_info(r, &info) == OCTOCAP_OK);
  return info;
}

}  // namespace

TEST_CASE("a take of picture folders: names, the shortest camera's length, every frame's own pictures", "[take]") {
  testing::TempDir dir;
  write_picture_take(dir, {6, 5, 6});
  std::filesystem::create_directories(dir.path() / "empty");  // a folder with no pictures is not a camera
  octocap_take_reader_t* r = nullptr;
  REQUIRE(octocap_take_reader_open(dir.path().c_str(), &r) == OCTOCAP_OK);
  const octocap_take_info_t info = info_of(r);
  CHECK(info.camera_count == 3);
  CHECK(info.frame_count == 5);
  CHECK(info.frames_per_second == 0);
  for (uint32_t c = 0; c < 3; ++c) {
    const char* name = nullptr;
    REQUIRE(octocap_take_reader_camera_name(r, c, &name) == OCTOCAP_OK);
    CHECK(std::string(name) == "cam" + std::to_string(c + 1));
  }
  octocap_image_t images[4];
  uint32_t count = 0;
  // In order, then back, then a jump ahead: each read gives that frame, exactly (PNG is lossless).
  for (int f : {0, 1, 2, 3, 4, 1, 0, 4, 2}) {
    REQUIRE(octocap_take_reader_read(r, static_cast<uint32_t>(f), images, 4, &count) == OCTOCAP_OK);
    REQUIRE(count == 3);
    for (int c = 0; c < 3; ++c) {
      CHECK(images[c].width == 64);
      CHECK(images[c].height == 48);
      CHECK(off_mark(images[c], c, f) == 0);
    }
  }
  octocap_take_reader_destroy(r);
}

TEST_CASE("a take reader's pictures stay the caller's frame while the next one decodes", "[take]") {
  testing::TempDir dir;
  write_picture_take(dir, {4, 4});
  octocap_take_reader_t* r = nullptr;
  REQUIRE(octocap_take_reader_open(dir.path().c_str(), &r) == OCTOCAP_OK);
  octocap_image_t images[2];
  for (int f = 0; f < 4; ++f) {
    REQUIRE(octocap_take_reader_read(r, static_cast<uint32_t>(f), images, 2, nullptr) == OCTOCAP_OK);
    std::this_thread::sleep_for(std::chrono::milliseconds(30));  // frame f + 1 has decoded by now, elsewhere
    CHECK(off_mark(images[0], 0, f) == 0);
    CHECK(off_mark(images[1], 1, f) == 0);
  }
  octocap_take_reader_destroy(r);
}

TEST_CASE("a take of videos: its rate, its length, and the frame asked for, forward and back", "[take]") {
  testing::TempDir dir;
  const int frames = 12;
  for (int c = 0; c < 2; ++c) {
    cv::VideoWriter writer(dir.file("view" + std::to_string(c) + ".avi"), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25,
                           cv::Size(64, 48));
    REQUIRE(writer.isOpened());
    for (int f = 0; f < frames; ++f) writer.write(cv::Mat(48, 64, CV_8UC3, mark(c, f)));
  }
  octocap_take_reader_t* r = nullptr;
  REQUIRE(octocap_take_reader_open(dir.path().c_str(), &r) == OCTOCAP_OK);
  const octocap_take_info_t info = info_of(r);
  CHECK(info.camera_count == 2);
  CHECK(info.frame_count == static_cast<uint32_t>(frames));
  CHECK(info.frames_per_second == 25.0);
  const char* name = nullptr;
  REQUIRE(octocap_take_reader_camera_name(r, 1, &name) == OCTOCAP_OK);
  CHECK(std::string(name) == "view1");
  octocap_image_t images[2];
  // A neighbouring frame's mark is 10 away: within 4 says it is this frame's picture.
  for (int f : {0, 1, 2, 7, 3, 11, 0, 5}) {
    REQUIRE(octocap_take_reader_read(r, static_cast<uint32_t>(f), images, 2, nullptr) == OCTOCAP_OK);
    CHECK(off_mark(images[0], 0, f) <= 4);
    CHECK(off_mark(images[1], 1, f) <= 4);
  }
  octocap_take_reader_destroy(r);
}

TEST_CASE("Pose2Sim's real take reads as OpenCV decodes the same videos, frame for frame", "[take][real]") {
  octocap_take_reader_t* r = nullptr;
  REQUIRE(octocap_take_reader_open(kRealVideos.c_str(), &r) == OCTOCAP_OK);
  const octocap_take_info_t info = info_of(r);
  REQUIRE(info.camera_count == 4);
  cv::VideoCapture own(kRealVideos + "/cam03.mp4");
  REQUIRE(own.isOpened());
  CHECK(info.frame_count == static_cast<uint32_t>(own.get(cv::CAP_PROP_FRAME_COUNT)));
  CHECK(info.frames_per_second == own.get(cv::CAP_PROP_FPS));
  std::vector<cv::Mat> truth;
  for (int f = 0; f < 25; ++f) {
    cv::Mat m;
    REQUIRE(own.read(m));
    truth.push_back(m.clone());
  }
  octocap_image_t images[4];
  for (int f : {0, 1, 2, 20, 24, 3}) {  // in order, a jump ahead, then back
    REQUIRE(octocap_take_reader_read(r, static_cast<uint32_t>(f), images, 4, nullptr) == OCTOCAP_OK);
    const cv::Mat got(static_cast<int>(images[2].height), static_cast<int>(images[2].width), CV_8UC3,
                      const_cast<uint8_t*>(images[2].pixels), images[2].stride_bytes);
    REQUIRE(got.size() == truth[f].size());
    CHECK(cv::norm(got, truth[f], cv::NORM_INF) == 0);
  }
  octocap_take_reader_destroy(r);
}

TEST_CASE("a take reader refuses what is not a take and misuse, with reasons", "[take][capi]") {
  testing::TempDir dir;
  octocap_take_reader_t* r = reinterpret_cast<octocap_take_reader_t*>(&dir);
  CHECK(octocap_take_reader_open(nullptr, &r) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(r == nullptr);
  CHECK(octocap_take_reader_open(dir.path().c_str(), nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_take_reader_open(dir.file("absent").c_str(), &r) == OCTOCAP_ERROR_IO);
  CHECK(octocap_take_reader_open(dir.path().c_str(), &r) == OCTOCAP_ERROR_IO);  // empty
  CHECK_THAT(octocap_last_error(), ContainsSubstring("neither videos"));
  dir.write("notes.txt", "not a picture");
  CHECK(octocap_take_reader_open(dir.path().c_str(), &r) == OCTOCAP_ERROR_IO);
  dir.write("broken.mp4", "not a video at all");
  CHECK(octocap_take_reader_open(dir.path().c_str(), &r) == OCTOCAP_ERROR_IO);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("broken.mp4"));

  testing::TempDir take;
  write_picture_take(take, {3, 3});
  // Frame 1 of the second camera is not a picture: that frame is an error naming the camera, the others read.
  take.write("cam2/000001.png", "garbage, not a PNG");
  REQUIRE(octocap_take_reader_open(take.path().c_str(), &r) == OCTOCAP_OK);
  octocap_image_t images[2];
  uint32_t count = 0;
  CHECK(octocap_take_reader_read(r, 0, images, 1, &count) == OCTOCAP_ERROR_BUFFER_TOO_SMALL);
  CHECK(count == 2);
  CHECK(octocap_take_reader_read(r, 0, nullptr, 2, &count) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_take_reader_read(r, 3, images, 2, &count) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("past the take's end"));
  REQUIRE(octocap_take_reader_read(r, 0, images, 2, &count) == OCTOCAP_OK);
  CHECK(octocap_take_reader_read(r, 1, images, 2, &count) == OCTOCAP_ERROR_IO);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("cam2"));
  REQUIRE(octocap_take_reader_read(r, 2, images, 2, &count) == OCTOCAP_OK);
  CHECK(off_mark(images[1], 1, 2) == 0);
  REQUIRE(octocap_take_reader_read(r, 0, images, 2, &count) == OCTOCAP_OK);
  CHECK(off_mark(images[1], 1, 0) == 0);

  const char* name = nullptr;
  CHECK(octocap_take_reader_camera_name(r, 2, &name) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_take_reader_camera_name(r, 0, nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_take_info_t info{};
  info.struct_size = 8;
  CHECK(octocap_take_reader_info(r, &info) == OCTOCAP_ERROR_STRUCT_SIZE);
  CHECK(octocap_take_reader_info(r, nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_take_reader_destroy(r);
  // Destroyed, NULL and foreign handles are refused without being touched.
  info.struct_size = sizeof info;
  CHECK(octocap_take_reader_info(r, &info) == OCTOCAP_ERROR_INVALID_HANDLE);
  CHECK(octocap_take_reader_read(r, 0, images, 2, &count) == OCTOCAP_ERROR_INVALID_HANDLE);
  CHECK(octocap_take_reader_camera_name(nullptr, 0, &name) == OCTOCAP_ERROR_INVALID_HANDLE);
  octocap_take_reader_destroy(r);  // twice: ignored
  octocap_take_reader_destroy(nullptr);
}
