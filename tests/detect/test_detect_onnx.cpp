// The ONNX path through the C ABI: a tiny model made here (known output for a known input), bad input, and the
// shipped models on real photos of people (hand-marked boxes below, from looking at the photos).
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <cstring>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "detect/detector.h"
#include "octocap/octocap.h"
#include "support/onnx_writer.h"
#include "support/temp_dir.h"

namespace {

struct DetectorDeleter {
  void operator()(octocap_detector_t* d) const { octocap_detector_destroy(d); }
};
using Detector = std::unique_ptr<octocap_detector_t, DetectorDeleter>;

const std::string kPhotos = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/photos/";

// The library's warnings while it lives, kept in `into`.
struct WarningsKept {
  explicit WarningsKept(std::vector<std::string>& into) {
    octocap_set_log_callback([](octocap_log_level_t level, const char* message, void* user) {
      if (level == OCTOCAP_LOG_WARNING) static_cast<std::vector<std::string>*>(user)->push_back(message);
    }, OCTOCAP_LOG_WARNING, &into);
  }
  ~WarningsKept() { octocap_set_log_callback(nullptr, OCTOCAP_LOG_WARNING, nullptr); }
  WarningsKept(const WarningsKept&) = delete;
  WarningsKept& operator=(const WarningsKept&) = delete;
};

octocap_result_t create(const std::string& model, octocap_detect_mode_t mode, Detector& out) {
  octocap_detector_config_t cfg;
  octocap_detector_config_init(&cfg);
  std::snprintf(cfg.model, sizeof cfg.model, "%s", model.c_str());
  cfg.mode = mode;
  cfg.threads = 1;
  octocap_detector_t* d = nullptr;
  const octocap_result_t r = octocap_detector_create(&cfg, &d);
  out.reset(d);
  return r;
}

octocap_image_t image_of(const cv::Mat& bgr) {
  return {bgr.data, static_cast<uint32_t>(bgr.cols), static_cast<uint32_t>(bgr.rows), static_cast<uint32_t>(bgr.step[0]),
          OCTOCAP_PIXELS_BGR8};
}

std::vector<std::vector<octocap_keypoint2d_t>> people_of(octocap_detector_t* d, uint32_t view) {
  uint32_t n = 0;
  REQUIRE(octocap_detector_people(d, view, &n) == OCTOCAP_OK);
  std::vector<std::vector<octocap_keypoint2d_t>> out(n, std::vector<octocap_keypoint2d_t>(17));
  for (uint32_t p = 0; p < n; ++p) {
    uint32_t count = 0;
    REQUIRE(octocap_detector_keypoints(d, view, p, out[p].data(), 17, &count) == OCTOCAP_OK);
    REQUIRE(count == 17);
  }
  return out;
}

// The tiny model: 17 heatmaps = a 1x1 convolution of the input; even keypoints follow red, odd ones green.
struct TinyModel {
  testing::TempDir dir;
  std::string path = dir.file("tiny.onnx");
  explicit TinyModel(int channels = 17, const std::string& card_kind = "heatmap") {
    std::vector<float> w;
    for (int k = 0; k < channels; ++k) w.insert(w.end(), {k % 2 == 0 ? 1.f : 0.f, k % 2 == 1 ? 1.f : 0.f, 0.f});
    testing::write_conv1x1_model(path, 32, 32, channels, w);
    dir.write("tiny.json", R"({"name": "tiny", "keypoint_layout": "COCO_17",
      "input": {"width": 32, "height": 32, "element_type": "float32", "tensor_layout": "NCHW", "channel_order": "RGB",
                "mean": [0, 0, 0], "scale": [0.00392157, 0.00392157, 0.00392157]},
      "output": {"kind": ")" + card_kind + R"(", "max_people": 1}})");
  }
};

// 64x64 black image (BGR) with a red blob at (20, 44) and a green one at (50, 12), Gaussian, sigma 3 px.
cv::Mat blob_image() {
  cv::Mat im(64, 64, CV_8UC3, cv::Scalar(0, 0, 0));
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      auto g = [&](double cx, double cy) { return 255 * std::exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / 18.0); };
      im.at<cv::Vec3b>(y, x) = cv::Vec3b(0, static_cast<uint8_t>(g(50, 12)), static_cast<uint8_t>(g(20, 44)));
    }
  return im;
}

void check_blobs(octocap_detector_t* d) {
  const auto people = people_of(d, 0);
  REQUIRE(people.size() == 1);
  for (int k = 0; k < 17; ++k) {
    INFO("keypoint " << k << " at " << people[0][k].x << ", " << people[0][k].y);
    const double tx = k % 2 == 0 ? 20 : 50, ty = k % 2 == 0 ? 44 : 12;
    CHECK(std::abs(people[0][k].x - tx) < 1.0);
    CHECK(std::abs(people[0][k].y - ty) < 1.0);
    CHECK(people[0][k].confidence > 0.8);
  }
}

// Mean y of the given keypoints that have confidence; NaN when none.
double mean_y(const std::vector<octocap_keypoint2d_t>& p, std::initializer_list<int> ks) {
  double s = 0;
  int n = 0;
  for (int k : ks)
    if (p[k].confidence >= 0.3) s += p[k].y, ++n;
  return n ? s / n : NAN;
}

// Eyes above shoulders above hips above knees above ankles, wherever both ends are visible.
void check_body_order(const std::vector<octocap_keypoint2d_t>& p) {
  const double levels[] = {mean_y(p, {1, 2}), mean_y(p, {5, 6}), mean_y(p, {11, 12}), mean_y(p, {13, 14}), mean_y(p, {15, 16})};
  for (int a = 0; a < 5; ++a)
    for (int b = a + 1; b < 5; ++b)
      if (!std::isnan(levels[a]) && !std::isnan(levels[b])) CHECK(levels[a] < levels[b]);
}

struct Box {
  double x0, y0, x1, y1;
  bool holds(const octocap_keypoint2d_t& k) const { return k.x >= x0 && k.x <= x1 && k.y >= y0 && k.y <= y1; }
};

// Every confident keypoint of the person lies in one of the hand-marked boxes; returns which, or -1.
int box_of(const std::vector<octocap_keypoint2d_t>& p, const std::vector<Box>& boxes) {
  for (size_t b = 0; b < boxes.size(); ++b) {
    int in = 0, confident = 0;
    for (const auto& k : p)
      if (k.confidence >= 0.3) ++confident, in += boxes[b].holds(k);
    if (confident >= 3 && in == confident) return static_cast<int>(b);
  }
  return -1;
}

// Hand-marked on the photos (pixels): whole people, generous by a few pixels.
const std::vector<Box> kBusPeople = {{40, 390, 255, 910}, {220, 395, 355, 870}, {660, 395, 810, 890}, {0, 550, 85, 875}};
const std::vector<Box> kZidanePeople = {{115, 190, 1165, 720}, {745, 35, 1160, 720}};
const Box kAstronautHead{145, 10, 305, 185};
const Box kAstronautBody{10, 10, 375, 512};

}  // namespace

TEST_CASE("a tiny ONNX model made here gives its known answer through the detector") {
  TinyModel model;
  Detector d;
  REQUIRE(create(model.path, OCTOCAP_DETECT_PER_VIEW, d) == OCTOCAP_OK);
  octocap_detect_info_t info{};
  info.struct_size = sizeof info;
  const cv::Mat bgr = blob_image();
  octocap_image_t im = image_of(bgr);
  REQUIRE(octocap_detector_run(d.get(), &im, 1) == OCTOCAP_OK);
  check_blobs(d.get());
  REQUIRE(octocap_detector_info(d.get(), &info) == OCTOCAP_OK);
  CHECK(info.inferences == 1);
  CHECK(info.layout == OCTOCAP_LAYOUT_COCO_17);
  CHECK(std::string(info.model) == "tiny");

  SECTION("RGB and RGBA pixels, padded rows") {
    cv::Mat rgb, rgba;
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    cv::cvtColor(bgr, rgba, cv::COLOR_BGR2RGBA);
    cv::Mat padded(64, 80 * 4, CV_8UC1, cv::Scalar(77));  // rows of 320 bytes holding 64 RGBA pixels
    rgba.copyTo(cv::Mat(64, 64, CV_8UC4, padded.data, 320));
    octocap_image_t a = {rgb.data, 64, 64, static_cast<uint32_t>(rgb.step[0]), OCTOCAP_PIXELS_RGB8};
    REQUIRE(octocap_detector_run(d.get(), &a, 1) == OCTOCAP_OK);
    check_blobs(d.get());
    octocap_image_t b = {padded.data, 64, 64, 320, OCTOCAP_PIXELS_RGBA8};
    REQUIRE(octocap_detector_run(d.get(), &b, 1) == OCTOCAP_OK);
    check_blobs(d.get());
  }
  SECTION("a crop of a bigger picture maps back to that picture's pixels") {
    cv::Mat big(300, 400, CV_8UC3, cv::Scalar(0, 0, 0));
    bgr.copyTo(big(cv::Rect(150, 100, 64, 64)));
    octocap_image_t b = image_of(big);
    REQUIRE(octocap_detector_run(d.get(), &b, 1) == OCTOCAP_OK);
    const auto people = people_of(d.get(), 0);
    REQUIRE(people.size() == 1);
    // 400x300 letterboxed into 32x32 is a 12.5x reduction: a pixel of the input is 12.5 of the picture.
    CHECK(std::abs(people[0][0].x - 170) < 7);
    CHECK(std::abs(people[0][0].y - 144) < 7);
  }
}

TEST_CASE("detector bad input gives clear errors") {
  TinyModel model;
  Detector d;
  REQUIRE(create(model.path, OCTOCAP_DETECT_PER_VIEW, d) == OCTOCAP_OK);
  const cv::Mat bgr = blob_image();
  auto run_with = [&](octocap_image_t im) { return octocap_detector_run(d.get(), &im, 1); };
  auto last = [] { return std::string(octocap_last_error()); };

  octocap_image_t ok = image_of(bgr);
  octocap_image_t im = ok;
  im.stride_bytes = 100;  // shorter than 64 x 3
  CHECK(run_with(im) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(last().find("stride") != std::string::npos);
  im = ok;
  im.pixels = nullptr;
  CHECK(run_with(im) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(last().find("NULL") != std::string::npos);
  im = ok;
  im.width = 0;
  CHECK(run_with(im) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(last().find("empty") != std::string::npos);
  im = ok;
  im.format = 7;
  CHECK(run_with(im) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(last().find("pixel format") != std::string::npos);
  CHECK(octocap_detector_run(d.get(), nullptr, 1) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_detector_run(d.get(), &ok, 0) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  uint32_t n = 0;
  CHECK(octocap_detector_people(d.get(), 3, &n) == OCTOCAP_ERROR_INVALID_ARGUMENT);

  // Figures: today's size gets the mode too; a 1.2 caller's struct (it ends before `mode`) is filled up to its end;
  // any other size is refused.
  REQUIRE(run_with(ok) == OCTOCAP_OK);
  octocap_detect_info_t info{};
  info.struct_size = sizeof info;
  info.mode = -1;
  REQUIRE(octocap_detector_info(d.get(), &info) == OCTOCAP_OK);
  CHECK(info.mode == OCTOCAP_DETECT_PER_VIEW);
  CHECK(info.inferences == 1);
  octocap_detect_info_t old{};
  old.struct_size = static_cast<uint32_t>(offsetof(octocap_detect_info_t, mode));
  old.mode = -1;
  REQUIRE(octocap_detector_info(d.get(), &old) == OCTOCAP_OK);
  CHECK(old.inferences == 1);
  CHECK(old.mode == -1);  // past the caller's struct: untouched
  old.struct_size = 12;
  CHECK(octocap_detector_info(d.get(), &old) == OCTOCAP_ERROR_STRUCT_SIZE);

  // A missing model, a missing card, a malformed card.
  Detector other;
  CHECK(create(model.dir.file("absent.onnx"), OCTOCAP_DETECT_PER_VIEW, other) == OCTOCAP_ERROR_IO);
  CHECK(last().find("absent") != std::string::npos);
  CHECK(other == nullptr);
  testing::write_conv1x1_model(model.dir.file("nocard.onnx"), 32, 32, 17, std::vector<float>(51, 0.f));
  CHECK(create(model.dir.file("nocard.onnx"), OCTOCAP_DETECT_PER_VIEW, other) == OCTOCAP_ERROR_IO);
  CHECK(last().find("model card") != std::string::npos);
  model.dir.write("bad.json", R"({"name": "bad", "keypoint_layout": "COCO_17", "input": {"width": 32}})");
  testing::write_conv1x1_model(model.dir.file("bad.onnx"), 32, 32, 17, std::vector<float>(51, 0.f));
  CHECK(create(model.dir.file("bad.onnx"), OCTOCAP_DETECT_PER_VIEW, other) == OCTOCAP_ERROR_PARSE);
  CHECK(last().find("height") != std::string::npos);
  // A file that is not an ONNX model at all.
  model.dir.write("junk.onnx", "this is not protobuf");
  model.dir.write("junk.json", R"({"name": "junk", "keypoint_layout": "COCO_17", "input": {"width": 32, "height": 32,
    "element_type": "float32", "tensor_layout": "NCHW", "channel_order": "RGB"}, "output": {"kind": "heatmap"}})");
  CHECK(create(model.dir.file("junk.onnx"), OCTOCAP_DETECT_PER_VIEW, other) == OCTOCAP_ERROR_PARSE);
  // The card's element type differs from the model's.
  model.dir.write("tiny_int.json", R"({"name": "x", "keypoint_layout": "COCO_17", "input": {"width": 32, "height": 32,
    "element_type": "int32", "tensor_layout": "NCHW", "channel_order": "RGB"}, "output": {"kind": "heatmap"}})");
  testing::write_conv1x1_model(model.dir.file("tiny_int.onnx"), 32, 32, 17, std::vector<float>(51, 0.f));
  CHECK(create(model.dir.file("tiny_int.onnx"), OCTOCAP_DETECT_PER_VIEW, other) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(last().find("element type") != std::string::npos);
  // The mosaic needs a multi-person model.
  CHECK(create(model.path, OCTOCAP_DETECT_MOSAIC, other) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(last().find("multi-person") != std::string::npos);

  // A model whose output does not have the shape its card promises: refused when it is loaded (one trial run), not
  // at the first frame of a live run and not guessed at.
  TinyModel five(5);
  CHECK(create(five.path, OCTOCAP_DETECT_PER_VIEW, other) == OCTOCAP_ERROR_PARSE);
  CHECK(last().find("do not fit its card") != std::string::npos);
  CHECK(last().find("expected [1,17") != std::string::npos);
  CHECK(other == nullptr);
  TinyModel fine(17);
  REQUIRE(create(fine.path, OCTOCAP_DETECT_PER_VIEW, other) == OCTOCAP_OK);

  // A destroyed handle.
  octocap_detector_t* raw = other.release();
  octocap_detector_destroy(raw);
  CHECK(octocap_detector_run(raw, &ok, 1) == OCTOCAP_ERROR_INVALID_HANDLE);
  octocap_detector_config_t cfg;
  octocap_detector_config_init(&cfg);
  cfg.struct_size = 12;
  octocap_detector_t* none = nullptr;
  CHECK(octocap_detector_create(&cfg, &none) == OCTOCAP_ERROR_STRUCT_SIZE);
  CHECK(none == nullptr);
}

TEST_CASE("MoveNet Thunder on a real portrait: face in the head, eyes above shoulders") {
  const cv::Mat photo = cv::imread(kPhotos + "astronaut.png", cv::IMREAD_COLOR);
  REQUIRE(!photo.empty());
  Detector d;
  REQUIRE(create("movenet-thunder", OCTOCAP_DETECT_PER_VIEW, d) == OCTOCAP_OK);
  octocap_image_t im = image_of(photo);
  REQUIRE(octocap_detector_run(d.get(), &im, 1) == OCTOCAP_OK);
  const auto people = people_of(d.get(), 0);
  REQUIRE(people.size() == 1);
  const auto& p = people[0];
  for (int k = 0; k <= 4; ++k) {  // nose, eyes, ears
    INFO("face keypoint " << k << " at " << p[k].x << ", " << p[k].y);
    CHECK(p[k].confidence >= 0.3);
    CHECK(kAstronautHead.holds(p[k]));
  }
  for (const auto& k : p)
    if (k.confidence >= 0.3) CHECK(kAstronautBody.holds(k));
  CHECK(p[1].x > p[2].x);  // her left eye (LEye) is on the image's right
  check_body_order(p);
}

TEST_CASE("MoveNet Thunder INT8 finds what the float model finds on real photos (VNNI CPUs); elsewhere it says why not") {
  // Loading the quantised model on a CPU without VNNI warns: ONNX Runtime's integer kernels there saturate (measured on
  // an AVX2-only AMD EPYC: median shift 7.8 px on zidane.jpg, 42 vs 35 mm on the real take), so the accuracy below
  // is what octocap promises on VNNI CPUs only (CI's), and the warning what it promises elsewhere.
  std::vector<std::string> warnings;
  {
    const WarningsKept kept(warnings);
    Detector d;
    REQUIRE(create("movenet-thunder-int8", OCTOCAP_DETECT_CROP, d) == OCTOCAP_OK);
    Detector float_model;
    REQUIRE(create("movenet-thunder", OCTOCAP_DETECT_CROP, float_model) == OCTOCAP_OK);
  }
  const bool vnni = octocap::internal::cpu_has_vnni();
  INFO("VNNI: " << vnni << ", warnings: " << warnings.size());
  REQUIRE(warnings.size() == (vnni ? 0u : 1u));  // the float model never warns
  if (!vnni) {
    CHECK(warnings[0].find("movenet-thunder-int8") != std::string::npos);
    CHECK(warnings[0].find("no VNNI") != std::string::npos);
    return;
  }
  // scripts/fetch-models.sh quantises it and checks one photo; here the product's path on two others.
  for (const char* name : {"astronaut.png", "zidane.jpg"}) {
    INFO(name);
    const cv::Mat photo = cv::imread(kPhotos + name, cv::IMREAD_COLOR);
    REQUIRE(!photo.empty());
    std::vector<octocap_keypoint2d_t> found[2];
    const char* models[2] = {"movenet-thunder", "movenet-thunder-int8"};
    for (int m = 0; m < 2; ++m) {
      Detector d;
      REQUIRE(create(models[m], OCTOCAP_DETECT_CROP, d) == OCTOCAP_OK);
      octocap_image_t im = image_of(photo);
      for (int frame = 0; frame < 2; ++frame) REQUIRE(octocap_detector_run(d.get(), &im, 1) == OCTOCAP_OK);
      const auto people = people_of(d.get(), 0);
      REQUIRE(people.size() == 1);
      found[m] = people[0];
    }
    std::vector<double> shift;
    size_t confident = 0;
    for (size_t k = 0; k < 17; ++k) {
      if (found[0][k].confidence < 0.3) continue;
      ++confident;
      if (found[1][k].confidence >= 0.3)
        shift.push_back(std::hypot(found[0][k].x - found[1][k].x, found[0][k].y - found[1][k].y));
    }
    REQUIRE(confident >= 8);
    CHECK(shift.size() >= 0.8 * confident);  // most of what the float model sees, the INT8 one sees too
    std::sort(shift.begin(), shift.end());
    // A few pixels of the photo's height (astronaut 512, zidane 720): measured median 1-3 px.
    CHECK(shift[shift.size() / 2] < 0.01 * photo.rows);
    CHECK(shift.back() < 0.05 * photo.rows);
  }
}

TEST_CASE("the crop path finds a person again on the whole view after a picture without anyone") {
  const cv::Mat photo = cv::imread(kPhotos + "astronaut.png", cv::IMREAD_COLOR);
  REQUIRE(!photo.empty());
  const cv::Mat empty(photo.rows, photo.cols, CV_8UC3, cv::Scalar(128, 128, 128));
  Detector d;
  REQUIRE(create("movenet-lightning", OCTOCAP_DETECT_CROP, d) == OCTOCAP_OK);
  for (const cv::Mat* picture : {&photo, &empty, &empty, &photo}) {
    octocap_image_t im = image_of(*picture);
    REQUIRE(octocap_detector_run(d.get(), &im, 1) == OCTOCAP_OK);
    const auto people = people_of(d.get(), 0);
    if (picture == &empty) {
      CHECK(people.empty());  // a grey picture: nobody (a crop left over from the last one is no person)
      continue;
    }
    REQUIRE(people.size() == 1);
    CHECK(people[0][0].confidence >= 0.3);  // the nose, in her head
    CHECK(kAstronautHead.holds(people[0][0]));
  }
}

TEST_CASE("MoveNet MultiPose on real street and sideline photos: people in their hand-marked boxes") {
  Detector d;
  REQUIRE(create("movenet-multipose", OCTOCAP_DETECT_PER_VIEW, d) == OCTOCAP_OK);
  const cv::Mat bus = cv::imread(kPhotos + "bus.jpg", cv::IMREAD_COLOR), zidane = cv::imread(kPhotos + "zidane.jpg", cv::IMREAD_COLOR);
  REQUIRE((!bus.empty() && !zidane.empty()));
  const octocap_image_t images[2] = {image_of(bus), image_of(zidane)};
  REQUIRE(octocap_detector_run(d.get(), images, 2) == OCTOCAP_OK);

  const auto on_bus = people_of(d.get(), 0);
  std::vector<int> found(kBusPeople.size(), 0);
  for (const auto& p : on_bus) {
    const int b = box_of(p, kBusPeople);
    CHECK(b >= 0);
    if (b >= 0) ++found[b];
    check_body_order(p);
  }
  CHECK(found[0] == 1);  // both people in full view, once each
  CHECK(found[1] == 1);
  const auto on_pitch = people_of(d.get(), 1);
  CHECK(on_pitch.size() >= 2);
  for (const auto& p : on_pitch) CHECK(box_of(p, kZidanePeople) >= 0);
}

TEST_CASE("the mosaic of three real photos maps every person back into its own photo") {
  Detector d;
  REQUIRE(create("", OCTOCAP_DETECT_MOSAIC, d) == OCTOCAP_OK);  // default: movenet-multipose
  const cv::Mat bus = cv::imread(kPhotos + "bus.jpg", cv::IMREAD_COLOR);
  const cv::Mat zidane = cv::imread(kPhotos + "zidane.jpg", cv::IMREAD_COLOR);
  const cv::Mat astronaut = cv::imread(kPhotos + "astronaut.png", cv::IMREAD_COLOR);
  const octocap_image_t images[3] = {image_of(bus), image_of(zidane), image_of(astronaut)};
  REQUIRE(octocap_detector_run(d.get(), images, 3) == OCTOCAP_OK);
  octocap_detect_info_t info{};
  info.struct_size = sizeof info;
  REQUIRE(octocap_detector_info(d.get(), &info) == OCTOCAP_OK);
  CHECK(info.inferences == 1);
  const auto on_bus = people_of(d.get(), 0);
  CHECK(!on_bus.empty());
  for (const auto& p : on_bus) CHECK(box_of(p, kBusPeople) >= 0);
  const auto on_pitch = people_of(d.get(), 1);
  CHECK(!on_pitch.empty());
  for (const auto& p : on_pitch) CHECK(box_of(p, kZidanePeople) >= 0);
  const auto astro = people_of(d.get(), 2);
  REQUIRE(!astro.empty());
  CHECK(box_of(astro[0], {kAstronautBody}) == 0);
  CHECK(kAstronautHead.holds(astro[0][0]));  // the nose
}

TEST_CASE("views inferred at once give exactly what one view after another gives") {
  const cv::Mat bus = cv::imread(kPhotos + "bus.jpg", cv::IMREAD_COLOR);
  const cv::Mat zidane = cv::imread(kPhotos + "zidane.jpg", cv::IMREAD_COLOR);
  const cv::Mat astronaut = cv::imread(kPhotos + "astronaut.png", cv::IMREAD_COLOR);
  const octocap_image_t images[3] = {image_of(bus), image_of(zidane), image_of(astronaut)};
  std::vector<std::vector<octocap_keypoint2d_t>> results[2];
  for (int run = 0; run < 2; ++run) {
    octocap_detector_config_t cfg;
    octocap_detector_config_init(&cfg);
    std::snprintf(cfg.model, sizeof cfg.model, "movenet-lightning");
    cfg.mode = OCTOCAP_DETECT_CROP;
    cfg.threads = 1;
    cfg.parallel_views = run == 0 ? 1 : 3;
    octocap_detector_t* raw = nullptr;
    REQUIRE(octocap_detector_create(&cfg, &raw) == OCTOCAP_OK);
    Detector d(raw);
    for (int frame = 0; frame < 2; ++frame)  // the second frame crops around the first one's people
      REQUIRE(octocap_detector_run(d.get(), images, 3) == OCTOCAP_OK);
    for (uint32_t v = 0; v < 3; ++v)
      for (const auto& p : people_of(d.get(), v)) results[run].push_back(p);
  }
  REQUIRE(results[0].size() == results[1].size());
  REQUIRE(!results[0].empty());
  for (size_t p = 0; p < results[0].size(); ++p)
    for (size_t k = 0; k < 17; ++k) {
      CHECK(results[0][p][k].x == results[1][p][k].x);
      CHECK(results[0][p][k].y == results[1][p][k].y);
      CHECK(results[0][p][k].confidence == results[1][p][k].confidence);
    }
}

TEST_CASE("the GPU is used when asked and there, else AUTO falls back to the CPU with a warning and CUDA says why") {
  std::vector<std::string> warnings;
  auto kept = std::make_unique<WarningsKept>(warnings);
  octocap_detector_config_t cfg;
  octocap_detector_config_init(&cfg);
  CHECK(cfg.device == OCTOCAP_DEVICE_CPU);  // a CPU user never loads CUDA libraries
  std::snprintf(cfg.model, sizeof cfg.model, "movenet-lightning");
  cfg.device = OCTOCAP_DEVICE_CUDA;
  octocap_detector_t* raw = nullptr;
  const octocap_result_t required = octocap_detector_create(&cfg, &raw);
  Detector cuda(raw);
  const std::string why = required == OCTOCAP_OK ? "" : octocap_last_error();
  cfg.device = OCTOCAP_DEVICE_AUTO;
  raw = nullptr;
  REQUIRE(octocap_detector_create(&cfg, &raw) == OCTOCAP_OK);  // AUTO always gives a detector
  Detector automatic(raw);
  cfg.device = 7;
  raw = nullptr;
  CHECK(octocap_detector_create(&cfg, &raw) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(std::string(octocap_last_error()).find("device 7") != std::string::npos);
  kept.reset();

  const cv::Mat photo = cv::imread(kPhotos + "astronaut.png", cv::IMREAD_COLOR);
  REQUIRE(!photo.empty());
  octocap_image_t im = image_of(photo);
  REQUIRE(octocap_detector_run(automatic.get(), &im, 1) == OCTOCAP_OK);
  octocap_detect_info_t info{};
  info.struct_size = sizeof info;
  REQUIRE(octocap_detector_info(automatic.get(), &info) == OCTOCAP_OK);
  const auto people = people_of(automatic.get(), 0);
  REQUIRE(people.size() == 1);
  CHECK(kAstronautHead.holds(people[0][0]));  // on either device, the nose in her head
  INFO("CUDA: " << (required == OCTOCAP_OK ? "available" : why));
  if (required == OCTOCAP_OK) {  // a GPU build on a machine with a GPU
    CHECK(info.device == OCTOCAP_DEVICE_CUDA);
    CHECK(warnings.empty());
    return;
  }
  // Here (CI: the CPU build of ONNX Runtime; or its GPU build on a machine without the NVIDIA driver, checked by hand
  // with LD_LIBRARY_PATH): CUDA refused, saying what is missing and how to get it; AUTO on the CPU.
  CHECK(required == OCTOCAP_ERROR_UNSUPPORTED);
  CHECK(why.find("no GPU for model movenet-lightning") != std::string::npos);
  CHECK((why.find("is the CPU build") != std::string::npos || why.find("cannot load") != std::string::npos));
  CHECK(why.find("install-deps.sh --gpu") != std::string::npos);
  CHECK(info.device == OCTOCAP_DEVICE_CPU);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("runs on the CPU") != std::string::npos);
}

TEST_CASE("a model's layout is read from its card without loading the network") {
  octocap_layout_t layout = OCTOCAP_LAYOUT_AUTO;
  REQUIRE(octocap_model_layout("movenet-thunder", &layout) == OCTOCAP_OK);
  CHECK(layout == OCTOCAP_LAYOUT_COCO_17);
  REQUIRE(octocap_model_layout("blazepose-full", &layout) == OCTOCAP_OK);
  CHECK(layout == OCTOCAP_LAYOUT_BLAZEPOSE_33);
  REQUIRE(octocap_model_layout("", &layout) == OCTOCAP_OK);  // the default model
  CHECK(layout == OCTOCAP_LAYOUT_COCO_17);
  CHECK(octocap_model_layout("no-such-model", &layout) == OCTOCAP_ERROR_IO);
  CHECK(std::string(octocap_last_error()).find("no-such-model") != std::string::npos);
  CHECK(octocap_model_layout(nullptr, &layout) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_model_layout("movenet-thunder", nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
}

namespace {

// The person a detector with `runtime` and `precision` finds in `photo` (the crop path, two frames), and its info.
std::vector<octocap_keypoint2d_t> person_with(octocap_runtime_t runtime, octocap_precision_t precision,
                                              const cv::Mat& photo, octocap_detect_info_t& info) {
  octocap_detector_config_t cfg;
  octocap_detector_config_init(&cfg);
  std::snprintf(cfg.model, sizeof cfg.model, "movenet-thunder");
  cfg.threads = 1;
  cfg.runtime = runtime;
  cfg.precision = precision;
  octocap_detector_t* raw = nullptr;
  INFO(octocap_last_error());
  REQUIRE(octocap_detector_create(&cfg, &raw) == OCTOCAP_OK);
  Detector d(raw);
  octocap_image_t im = image_of(photo);
  for (int frame = 0; frame < 2; ++frame) REQUIRE(octocap_detector_run(d.get(), &im, 1) == OCTOCAP_OK);
  info = {};
  info.struct_size = sizeof info;
  REQUIRE(octocap_detector_info(d.get(), &info) == OCTOCAP_OK);
  const auto people = people_of(d.get(), 0);
  REQUIRE(people.size() == 1);
  return people[0];
}

// Pixel distances between two detections' keypoints where the first is confident, sorted; `missed` counts those the
// second lost.
std::vector<double> shifts(const std::vector<octocap_keypoint2d_t>& a, const std::vector<octocap_keypoint2d_t>& b,
                           size_t& missed) {
  std::vector<double> d;
  missed = 0;
  for (size_t k = 0; k < a.size(); ++k) {
    if (a[k].confidence < 0.3) continue;
    if (b[k].confidence < 0.3) ++missed;
    else d.push_back(std::hypot(a[k].x - b[k].x, a[k].y - b[k].y));
  }
  std::sort(d.begin(), d.end());
  return d;
}

}  // namespace

TEST_CASE("OpenVINO finds what ONNX Runtime finds on real photos: the same keypoints at f32, within pixels reduced") {
  if (std::string(octocap_openvino_version()).empty()) {
    // A build without OpenVINO (OCTOCAP_WITH_OPENVINO=OFF) says so when asked for it, and AUTO is ONNX Runtime.
    octocap_detector_config_t cfg;
    octocap_detector_config_init(&cfg);
    std::snprintf(cfg.model, sizeof cfg.model, "movenet-lightning");
    cfg.runtime = OCTOCAP_RUNTIME_OPENVINO;
    octocap_detector_t* raw = nullptr;
    CHECK(octocap_detector_create(&cfg, &raw) == OCTOCAP_ERROR_UNSUPPORTED);
    CHECK(std::string(octocap_last_error()).find("without OpenVINO") != std::string::npos);
    return;
  }
  for (const char* name : {"astronaut.png", "zidane.jpg"}) {
    INFO(name);
    const cv::Mat photo = cv::imread(kPhotos + name, cv::IMREAD_COLOR);
    REQUIRE(!photo.empty());
    octocap_detect_info_t ort_info, ov_info, reduced_info, auto_info;
    const auto ort = person_with(OCTOCAP_RUNTIME_ONNXRUNTIME, OCTOCAP_PRECISION_AUTO, photo, ort_info);
    const auto ov = person_with(OCTOCAP_RUNTIME_OPENVINO, OCTOCAP_PRECISION_F32, photo, ov_info);
    const auto reduced = person_with(OCTOCAP_RUNTIME_OPENVINO, OCTOCAP_PRECISION_REDUCED, photo, reduced_info);
    person_with(OCTOCAP_RUNTIME_AUTO, OCTOCAP_PRECISION_AUTO, photo, auto_info);
    CHECK(ort_info.runtime == OCTOCAP_RUNTIME_ONNXRUNTIME);
    CHECK(ort_info.precision == OCTOCAP_PRECISION_F32);
    CHECK(ov_info.runtime == OCTOCAP_RUNTIME_OPENVINO);
    CHECK(ov_info.precision == OCTOCAP_PRECISION_F32);
    CHECK(auto_info.runtime == OCTOCAP_RUNTIME_OPENVINO);  // the CPU's default back end where the build has it
    CHECK(reduced_info.runtime == OCTOCAP_RUNTIME_OPENVINO);
    size_t missed = 0;
    const std::vector<double> same = shifts(ort, ov, missed);
    REQUIRE(same.size() >= 8);
    CHECK(missed == 0);
    // The same network in the same arithmetic: the same keypoints to rounding (measured: 0.01-0.12 px median; one
    // keypoint of zidane.jpg 4 px, where the second frame's crop, placed from the first, differs by a pixel).
    CHECK(same[same.size() / 2] < 0.5);
    CHECK(same.back() < 0.01 * photo.rows);
    CHECK(auto_info.precision == OCTOCAP_PRECISION_F32);
    // bf16 where the CPU has it (else OpenVINO keeps f32 and reports it): measured median 1-4 px, worst 13 px, and
    // zidane's hips (confidence 0.57 at f32) lost.
    const std::vector<double> near = shifts(ort, reduced, missed);
    REQUIRE(near.size() >= 6);
    CHECK(missed * 4 <= near.size() + missed);
    CHECK(near[near.size() / 2] < 0.01 * photo.rows);
    CHECK(near.back() < 0.05 * photo.rows);
  }
}

TEST_CASE("runtime and precision: unknown values and impossible pairs are refused, saying why") {
  octocap_detector_config_t cfg;
  octocap_detector_config_init(&cfg);
  CHECK(cfg.runtime == OCTOCAP_RUNTIME_AUTO);
  CHECK(cfg.precision == OCTOCAP_PRECISION_AUTO);
  std::snprintf(cfg.model, sizeof cfg.model, "movenet-lightning");
  octocap_detector_t* raw = nullptr;
  cfg.runtime = 9;
  CHECK(octocap_detector_create(&cfg, &raw) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(std::string(octocap_last_error()).find("runtime 9") != std::string::npos);
  cfg.runtime = OCTOCAP_RUNTIME_AUTO;
  cfg.precision = -1;
  CHECK(octocap_detector_create(&cfg, &raw) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(std::string(octocap_last_error()).find("precision -1") != std::string::npos);
  cfg.runtime = OCTOCAP_RUNTIME_ONNXRUNTIME;
  cfg.precision = OCTOCAP_PRECISION_REDUCED;
  CHECK(octocap_detector_create(&cfg, &raw) == OCTOCAP_ERROR_UNSUPPORTED);
  CHECK(std::string(octocap_last_error()).find("reduced precision needs OpenVINO") != std::string::npos);
  cfg.runtime = OCTOCAP_RUNTIME_OPENVINO;
  cfg.precision = OCTOCAP_PRECISION_AUTO;
  cfg.device = OCTOCAP_DEVICE_CUDA;
  CHECK(octocap_detector_create(&cfg, &raw) == OCTOCAP_ERROR_UNSUPPORTED);
  CHECK(std::string(octocap_last_error()).find("CPU only") != std::string::npos);
  CHECK(raw == nullptr);
  // A 1.8 caller's config (no runtime, no precision) gets the defaults.
  octocap_detector_config_t old;
  REQUIRE(octocap_detector_config_defaults(&old, 552) == OCTOCAP_OK);
  CHECK(old.struct_size == 552);
}
