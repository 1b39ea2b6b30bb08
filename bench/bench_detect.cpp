// 2D detection benchmark on real camera frames (Pose2Sim's demo videos, 1088x1920): ms per frame for 1, 4 and 8
// views, per path (per view, mosaic, crop) and model, with 1 and 2 ONNX Runtime threads; then each path's accuracy
// on the whole 4-camera take: keypoints solved, reprojection error, distance to Pose2Sim's own 3D.
// `--end-to-end [LEVER]`: frames/s from the videos with decoding, per stage, per lever (model, views detected a frame),
// for 1, 4 and 8 views. `--accuracy [PATH]`, `--crop-gap`: those tables alone. `--runtimes`: per inference back end
// and precision, ms per inference alone and two at once per model, then the accuracy of the main paths in each.
// Run after scripts/fetch-models.sh and scripts/fetch-real-videos.sh (scripts/test.sh fetches both).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <future>
#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

#include "capture/picture_pool.h"
#include "pose2sim_reference.h"
#include "octocap/octocap.h"

namespace {

const std::string kVideos = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/pose2sim-0.10.49/Demo_SinglePerson/videos/";
const std::string kDemo = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/pose2sim-0.4.15/Demo";

struct Path {
  const char* name;
  octocap_detect_mode_t mode;
  const char* model;
  uint32_t parallel_views;
  octocap_layout_t layout = OCTOCAP_LAYOUT_COCO_17;
  uint32_t views_per_frame = 0;  // detection scheduling: the other views followed by optical flow
};
const Path kPaths[] = {{"per-view lightning", OCTOCAP_DETECT_PER_VIEW, "movenet-lightning", 1},
                       {"per-view thunder", OCTOCAP_DETECT_PER_VIEW, "movenet-thunder", 1},
                       {"crop thunder", OCTOCAP_DETECT_CROP, "movenet-thunder", 1},
                       {"crop thunder, 2 views at once", OCTOCAP_DETECT_CROP, "movenet-thunder", 2},
                       {"crop thunder int8", OCTOCAP_DETECT_CROP, "movenet-thunder-int8", 1},
                       {"crop thunder int8, 2 views at once", OCTOCAP_DETECT_CROP, "movenet-thunder-int8", 2},
                       {"crop blazepose lite, 2 views at once", OCTOCAP_DETECT_CROP, "blazepose-lite", 2,
                        OCTOCAP_LAYOUT_BLAZEPOSE_33},
                       {"crop blazepose full, 2 views at once", OCTOCAP_DETECT_CROP, "blazepose-full", 2,
                        OCTOCAP_LAYOUT_BLAZEPOSE_33},
                       {"mosaic multipose", OCTOCAP_DETECT_MOSAIC, "movenet-multipose", 1},
                       {"crop thunder, 1 view detected a frame, 3 followed by flow", OCTOCAP_DETECT_CROP,
                        "movenet-thunder", 1, OCTOCAP_LAYOUT_COCO_17, 1},
                       {"crop thunder, 2 views detected a frame (at once), 2 followed", OCTOCAP_DETECT_CROP,
                        "movenet-thunder", 2, OCTOCAP_LAYOUT_COCO_17, 2},
                       {"crop lightning, 2 views at once", OCTOCAP_DETECT_CROP, "movenet-lightning", 2},
                       {"crop lightning, 1 view detected a frame, 3 followed by flow", OCTOCAP_DETECT_CROP,
                        "movenet-lightning", 1, OCTOCAP_LAYOUT_COCO_17, 1},
                       {"crop lightning, 2 views detected a frame (at once), 2 followed", OCTOCAP_DETECT_CROP,
                        "movenet-lightning", 2, OCTOCAP_LAYOUT_COCO_17, 2}};

// Keypoints scored apart from the body: MoveNet has none of them.
bool is_foot(const char* name) { return std::strstr(name, "Heel") || std::strstr(name, "Toe") || std::strstr(name, "FootIndex"); }

// The back end every detector of a table runs in (--runtimes sets it per table; default: the library's choice).
octocap_runtime_t g_runtime = OCTOCAP_RUNTIME_AUTO;
octocap_precision_t g_precision = OCTOCAP_PRECISION_AUTO;

// threads 0 with parallel views: each view's inference gets cores / parallel views.
octocap_detector_config_t config_of(const Path& p, uint32_t threads) {
  octocap_detector_config_t c;
  octocap_detector_config_init(&c);
  c.runtime = g_runtime;
  c.precision = g_precision;
  std::snprintf(c.model, sizeof c.model, "%s", p.model);
  c.mode = p.mode;
  c.threads = p.parallel_views > 1 ? 0 : threads;
  c.parallel_views = p.parallel_views;
  c.views_per_frame = p.views_per_frame;
  return c;
}

std::vector<std::vector<cv::Mat>> read_frames(int count) {
  std::vector<std::vector<cv::Mat>> frames(count);
  for (int c = 1; c <= 4; ++c) {
    cv::VideoCapture video(kVideos + "cam0" + std::to_string(c) + ".mp4");
    for (int f = 0; f < count; ++f) {
      cv::Mat m;
      if (!video.read(m)) return {};
      frames[f].push_back(m);
    }
  }
  return frames;
}

std::vector<octocap_image_t> views_of(const std::vector<cv::Mat>& images, size_t n) {
  std::vector<octocap_image_t> v;
  for (size_t i = 0; i < n; ++i) {
    const cv::Mat& m = images[i % images.size()];
    v.push_back({m.data, static_cast<uint32_t>(m.cols), static_cast<uint32_t>(m.rows), static_cast<uint32_t>(m.step[0]),
                 OCTOCAP_PIXELS_BGR8});
  }
  return v;
}

// The last solve's layout keypoints (person 0); all invalid when nobody was solved.
void last_keypoints(const octocap_session_t* s, octocap_joint_t* out, uint32_t capacity) {
  for (uint32_t k = 0; k < capacity; ++k) out[k].valid = 0;
  octocap_frame_t* f = nullptr;
  uint32_t n = 0;
  if (octocap_session_get_frame(s, &f) == OCTOCAP_OK) octocap_frame_get_keypoints3d(f, 0, out, capacity, &n);
  octocap_frame_release(f);
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

void speed(const std::vector<std::vector<cv::Mat>>& frames) {
  std::printf("\n## Detection speed, ms per frame (all views), real 1088x1920 frames, this machine\n\n");
  std::printf("| path | threads | 1 view | 4 views | 8 views | inferences (8 views) |\n|---|---|---|---|---|---|\n");
  for (const Path& p : kPaths)
    for (uint32_t threads : {1u, 2u}) {
      if (p.parallel_views > 1 && threads == 1) continue;  // the views share the cores: one row
      std::printf("| %s | %u |", p.name, threads);
      uint32_t inferences = 0;
      for (size_t n : {1u, 4u, 8u}) {
        const octocap_detector_config_t cfg = config_of(p, threads);
        octocap_detector_t* d = nullptr;
        if (octocap_detector_create(&cfg, &d) != OCTOCAP_OK) {
          std::printf(" %s |", octocap_last_error());
          continue;
        }
        double total = 0;
        int runs = 0;
        for (size_t f = 0; f < frames.size(); ++f) {
          const auto views = views_of(frames[f], n);
          octocap_detector_run(d, views.data(), static_cast<uint32_t>(n));
          octocap_detect_info_t info{};
          info.struct_size = sizeof info;
          octocap_detector_info(d, &info);
          if (f >= 2) total += info.total_ms, ++runs;  // the first frames warm up ONNX Runtime (and find the crops)
          inferences = info.inferences;
        }
        std::printf(" %.1f |", total / runs);
        octocap_detector_destroy(d);
      }
      std::printf(" %u |\n", inferences);
    }
}

// only: rows whose name contains it (empty: every row).
void accuracy(const std::string& only = "") {
  octocap_calibration_t* calib = nullptr;
  if (octocap_calibration_load((kDemo + "/calibration/Calib_qualisys.toml").c_str(), &calib) != OCTOCAP_OK) {
    std::printf("no calibration: %s\n", octocap_last_error());
    return;
  }
  const auto frames = read_frames(100);
  std::printf("\n## Accuracy on the real 4-camera take (100 frames, triangulation, no filter, 2 threads)\n\n");
  std::printf("| path | keypoints solved | median reprojection px | median / mean distance to Pose2Sim 3D, mm "
              "(body) | feet keypoints solved, heels' median distance mm | detect ms/frame |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const Path& p : kPaths) {
    if (std::string(p.name).find(only) == std::string::npos) continue;
    octocap_session_config_t cfg;
    octocap_session_config_init(&cfg);
    cfg.layout = p.layout;
    cfg.filter = OCTOCAP_FILTER_NONE;
    octocap_session_t* s = nullptr;
    if (octocap_session_create(&cfg, calib, &s) != OCTOCAP_OK) continue;
    const octocap_detector_config_t detector = config_of(p, 2);
    if (octocap_session_set_detector(s, &detector) != OCTOCAP_OK) {
      std::printf("| %s | %s |\n", p.name, octocap_last_error());
      octocap_session_destroy(s);
      continue;
    }
    const uint32_t K = octocap_layout_keypoint_count(p.layout);
    // Body and feet scored apart, each with its own reference (the reference matches keypoints by name).
    std::vector<octocap_joint_t> joints(K), body(K), feet(K);
    testing::Pose2SimReference body_score(kDemo + "/opensim/Balancing_for_IK.trc", p.layout);
    testing::Pose2SimReference feet_score(kDemo + "/opensim/Balancing_for_IK.trc", p.layout);
    size_t feet_keypoints = 0;
    for (uint32_t k = 0; k < K; ++k) feet_keypoints += is_foot(octocap_layout_keypoint_name(p.layout, k));
    double detect_ms = 0;
    for (size_t f = 0; f < frames.size(); ++f) {
      const auto views = views_of(frames[f], 4);
      const octocap_result_t r = octocap_session_solve_images(s, views.data(), 4, static_cast<int64_t>(f) * 16667);
      octocap_detect_info_t info{};
      info.struct_size = sizeof info;
      octocap_session_detect_info(s, &info);
      detect_ms += info.total_ms;
      if (r != OCTOCAP_OK) continue;
      last_keypoints(s, joints.data(), K);
      for (uint32_t k = 0; k < K; ++k) {
        const bool foot = is_foot(octocap_layout_keypoint_name(p.layout, k));
        body[k] = joints[k], feet[k] = joints[k];
        (foot ? body[k] : feet[k]).valid = 0;
      }
      body_score.add(f, body.data());
      feet_score.add(f, feet.data());
    }
    std::vector<double> dist, feet_dist;
    for (double d : body_score.distance_m) dist.push_back(1000 * d);
    for (double d : feet_score.distance_m) feet_dist.push_back(1000 * d);
    double mean = 0;
    for (double d : dist) mean += d;
    char heels[64] = "-";
    if (feet_keypoints)
      std::snprintf(heels, sizeof heels, "%.1f %%, %.0f mm", 100.0 * feet_score.solved / (feet_keypoints * frames.size()),
                    median(feet_dist));
    std::printf("| %s | %.1f %% | %.2f | %.1f / %.1f | %s | %.1f |\n", p.name,
                100.0 * (body_score.solved + feet_score.solved) / (static_cast<double>(K) * frames.size()),
                median(body_score.reprojection_px), median(dist), dist.empty() ? NAN : mean / dist.size(), heels,
                detect_ms / frames.size());
    octocap_session_destroy(s);
  }
  octocap_calibration_destroy(calib);
}

// Crops follow the person from the last solved frame: the longer the gap between detections (a live engine that
// takes the newest pictures when it is free), the further the person has moved. Every step-th frame of the take is
// detected (at 60 fps: step 6 is 100 ms between detections), as a loaded live engine would.
void crop_gap() {
  octocap_calibration_t* calib = nullptr;
  if (octocap_calibration_load((kDemo + "/calibration/Calib_qualisys.toml").c_str(), &calib) != OCTOCAP_OK) return;
  const int kFrames = 240;
  std::printf("\n## Crops with frames between detections (the first %d frames of the take, 60 fps, 2 threads)\n\n", kFrames);
  std::printf("| model | detected every | ms between detections | keypoints solved | median distance to Pose2Sim 3D, mm |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const char* model : {"movenet-lightning", "movenet-thunder"})
    for (int step : {1, 3, 6, 10}) {
      octocap_session_config_t cfg;
      octocap_session_config_init(&cfg);
      cfg.layout = OCTOCAP_LAYOUT_COCO_17;
      cfg.filter = OCTOCAP_FILTER_NONE;
      octocap_session_t* s = nullptr;
      if (octocap_session_create(&cfg, calib, &s) != OCTOCAP_OK) continue;
      const octocap_detector_config_t detector = config_of({model, OCTOCAP_DETECT_CROP, model, 1, OCTOCAP_LAYOUT_COCO_17}, 2);
      if (octocap_session_set_detector(s, &detector) != OCTOCAP_OK) {
        octocap_session_destroy(s);
        continue;
      }
      testing::Pose2SimReference score(kDemo + "/opensim/Balancing_for_IK.trc", OCTOCAP_LAYOUT_COCO_17);
      std::vector<cv::VideoCapture> videos;
      for (int c = 1; c <= 4; ++c) videos.emplace_back(kVideos + "cam0" + std::to_string(c) + ".mp4");
      std::vector<cv::Mat> images(4);
      size_t detected = 0;
      for (int f = 0; f < kFrames; ++f) {
        bool all = true;
        for (int c = 0; c < 4; ++c) all = videos[c].read(images[c]) && all;
        if (!all) break;
        if (f % step != 0) continue;
        const auto views = views_of(images, 4);
        ++detected;
        if (octocap_session_solve_images(s, views.data(), 4, static_cast<int64_t>(f) * 16667) != OCTOCAP_OK) continue;
        octocap_joint_t j[17];
        last_keypoints(s, j, 17);
        score.add(static_cast<size_t>(f), j);
      }
      std::vector<double> dist;
      for (double d : score.distance_m) dist.push_back(1000 * d);
      std::printf("| %s | %d | %.0f | %.1f %% | %.1f |\n", model, step, step * 16.667,
                  detected ? 100.0 * score.solved / (17.0 * detected) : 0.0, median(dist));
      octocap_session_destroy(s);
    }
  octocap_calibration_destroy(calib);
}

// End to end from the videos as `octocap solve --images` runs them: the next frame decoded on another thread (one
// ahead, into reused buffers) while this one is detected and solved. Per lever and view count (8: the four videos
// twice, each decoded on its own): frames/s, and per frame the stages: decoding (on its thread), how long the frame
// waited for it, detection (wall), within it the views' pre-processing, network and optical flow (summed over the
// views, which run two at a time), then the 3D solve, filter and rig. One view is detected only (no 3D from one).
struct Lever {
  const char* name;
  const char* model;
  uint32_t views_per_frame;
};
const Lever kLevers[] = {{"Thunder (default)", "movenet-thunder", 0},
                         {"Thunder, 2 views detected a frame", "movenet-thunder", 2},
                         {"Thunder, 1 view detected a frame", "movenet-thunder", 1},
                         {"Thunder INT8", "movenet-thunder-int8", 0},
                         {"Lightning", "movenet-lightning", 0},
                         {"Lightning, 2 views detected a frame", "movenet-lightning", 2},
                         {"Lightning, 1 view detected a frame", "movenet-lightning", 1}};

class Decoder {
 public:
  explicit Decoder(size_t views) : buffers_(views) {
    for (size_t v = 0; v < views; ++v) videos_.emplace_back(kVideos + "cam0" + std::to_string(v % 4 + 1) + ".mp4");
    ahead_ = std::async(std::launch::async, [this] { return decode(); });
  }
  ~Decoder() { if (ahead_.valid()) ahead_.wait(); }
  // The frame decoded ahead (empty at the end), and the next one started; `waited_ms`: how long it was not ready.
  std::vector<cv::Mat> next(double& waited_ms) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<cv::Mat> frame = ahead_.get();
    waited_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!frame.empty()) ahead_ = std::async(std::launch::async, [this] { return decode(); });
    return frame;
  }
  double decode_ms = 0;  // all frames, on the decoding thread

 private:
  std::vector<cv::Mat> decode() {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<cv::Mat> frame(videos_.size());
    for (size_t v = 0; v < videos_.size(); ++v) {
      cv::Mat& into = buffers_[v].next();  // as the live feeds: a buffer nobody holds any more
      if (!videos_[v].read(into)) return {};
      frame[v] = into;
    }
    decode_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return frame;
  }
  std::vector<cv::VideoCapture> videos_;
  std::vector<octocap::internal::PicturePool> buffers_;
  std::future<std::vector<cv::Mat>> ahead_;
};

void end_to_end(const std::string& only) {
  octocap_calibration_t* four = nullptr;
  if (octocap_calibration_load((kDemo + "/calibration/Calib_qualisys.toml").c_str(), &four) != OCTOCAP_OK) {
    std::printf("no calibration: %s\n", octocap_last_error());
    return;
  }
  std::vector<octocap_camera_t> cams(8);
  for (uint32_t c = 0; c < 8; ++c) {
    octocap_calibration_get_camera(four, c % 4, &cams[c]);
    std::snprintf(cams[c].name, sizeof cams[c].name, "cam%u", c + 1);
  }
  octocap_calibration_t* eight = nullptr;
  if (octocap_calibration_create(cams.data(), 8, &eight) != OCTOCAP_OK) {
    std::printf("no 8-camera calibration: %s\n", octocap_last_error());
    octocap_calibration_destroy(four);
    return;
  }
  std::printf("\n## End to end from the videos (1088x1920 H.264, decoding included, 100 frames), ms per frame\n\n");
  std::printf("| lever | views | frames/s | decoding (its thread) | waited for decoding | detection | pre-process, "
              "network, flow (summed over views) | 3D, filter, rig | network runs |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const Lever& lever : kLevers) {
    if (std::string(lever.name).find(only) == std::string::npos) continue;
    for (size_t n : {1u, 4u, 8u}) {
      octocap_detector_config_t d;
      octocap_detector_config_init(&d);
      std::snprintf(d.model, sizeof d.model, "%s", lever.model);
      d.views_per_frame = lever.views_per_frame;
      octocap_session_t* s = nullptr;
      octocap_detector_t* alone = nullptr;  // one view: detection only
      octocap_session_config_t cfg;
      octocap_session_config_init(&cfg);
      cfg.layout = OCTOCAP_LAYOUT_COCO_17;
      const bool ok = n == 1 ? octocap_detector_create(&d, &alone) == OCTOCAP_OK
                             : octocap_session_create(&cfg, n == 4 ? four : eight, &s) == OCTOCAP_OK &&
                                   octocap_session_set_detector(s, &d) == OCTOCAP_OK;
      if (!ok) {
        std::printf("| %s | %zu | %s |\n", lever.name, n, octocap_last_error());
        octocap_session_destroy(s);
        octocap_detector_destroy(alone);
        continue;
      }
      Decoder decoder(n);
      double waited = 0, detection = 0, pre = 0, network = 0, flow = 0, solve = 0, runs = 0;
      int frames = 0;
      const auto start = std::chrono::steady_clock::now();
      for (;;) {
        double w = 0;
        const std::vector<cv::Mat> frame = decoder.next(w);
        if (frame.empty()) break;
        const auto t0 = std::chrono::steady_clock::now();
        const auto views = views_of(frame, n);
        octocap_detect_info_t info{};
        info.struct_size = sizeof info;
        if (alone) {
          octocap_detector_run(alone, views.data(), static_cast<uint32_t>(n));
          octocap_detector_info(alone, &info);
        } else {
          octocap_session_solve_images(s, views.data(), static_cast<uint32_t>(n), static_cast<int64_t>(frames) * 16667);
          octocap_session_detect_info(s, &info);
        }
        const double frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        waited += w, detection += info.total_ms, pre += info.preprocess_ms, network += info.inference_ms;
        flow += info.track_ms, solve += frame_ms - info.total_ms, runs += info.inferences;
        ++frames;
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      char solved[32] = "-";
      if (s) std::snprintf(solved, sizeof solved, "%.2f", solve / frames);
      std::printf("| %s | %zu | %.1f | %.1f | %.1f | %.1f | %.1f, %.1f, %.1f | %s | %.2f |\n", lever.name, n,
                  frames / seconds, decoder.decode_ms / frames, waited / frames, detection / frames, pre / frames,
                  network / frames, flow / frames, solved, runs / frames);
      std::fflush(stdout);
      octocap_session_destroy(s);
      octocap_detector_destroy(alone);
    }
  }
  octocap_calibration_destroy(eight);
  octocap_calibration_destroy(four);
}

// Per back end and precision: one inference's cost (the crop path on one view, one thread), and two views' at once
// (two threads, each view on its own: the memory bandwidth they share shows), per model; then the accuracy table's
// main paths in each, so that a faster arithmetic is judged by the 3D it gives.
void runtimes(const std::vector<std::vector<cv::Mat>>& frames) {
  struct Backend {
    const char* name;
    octocap_runtime_t runtime;
    octocap_precision_t precision;
  };
  const Backend backends[] = {{"ONNX Runtime f32", OCTOCAP_RUNTIME_ONNXRUNTIME, OCTOCAP_PRECISION_F32},
                              {"OpenVINO f32", OCTOCAP_RUNTIME_OPENVINO, OCTOCAP_PRECISION_F32},
                              {"OpenVINO reduced", OCTOCAP_RUNTIME_OPENVINO, OCTOCAP_PRECISION_REDUCED}};
  const char* models[] = {"movenet-thunder", "movenet-lightning", "movenet-thunder-int8", "blazepose-full",
                          "blazepose-lite"};
  std::printf("\n## Inference back ends: ms per inference, crop path, real 1088x1920 frames, this machine\n\n");
  std::printf("| back end | model | precision run | 1 view, 1 thread | 2 views at once, each |\n|---|---|---|---|---|\n");
  for (const Backend& b : backends)
    for (const char* model : models) {
      g_runtime = b.runtime;
      g_precision = b.precision;
      std::printf("| %s | %s |", b.name, model);
      const char* ran = "-";
      for (uint32_t views : {1u, 2u}) {
        const octocap_detector_config_t cfg = config_of({model, OCTOCAP_DETECT_CROP, model, views}, 1);
        octocap_detector_t* d = nullptr;
        if (octocap_detector_create(&cfg, &d) != OCTOCAP_OK) {
          std::printf(" %s | %s |", ran, octocap_last_error());
          break;
        }
        std::vector<double> per_inference;
        for (size_t f = 0; f < frames.size(); ++f) {
          const auto v = views_of(frames[f], views);
          octocap_detector_run(d, v.data(), views);
          octocap_detect_info_t info{};
          info.struct_size = sizeof info;
          octocap_detector_info(d, &info);
          ran = info.precision == OCTOCAP_PRECISION_REDUCED ? "bf16" : "f32";
          // Wall time of the frame: views at once overlap, so each view's inference costs the frame's time.
          if (f >= 2 && info.inferences) per_inference.push_back(info.total_ms * views / info.inferences);
        }
        if (views == 1) std::printf(" %s |", ran);
        std::printf(" %.1f |", median(per_inference));
        octocap_detector_destroy(d);
      }
      std::printf("\n");
      std::fflush(stdout);
    }
  for (const Backend& b : backends) {
    g_runtime = b.runtime;
    g_precision = b.precision;
    std::printf("\n### %s\n", b.name);
    accuracy("crop thunder, 2 views at once");
    accuracy("crop lightning, 2 views at once");
    accuracy("crop blazepose full");
  }
  g_runtime = OCTOCAP_RUNTIME_AUTO;
  g_precision = OCTOCAP_PRECISION_AUTO;
}

}  // namespace

int main(int argc, char** argv) {
  std::printf("# octocap 2D detection benchmark (ONNX Runtime %s, OpenVINO %s)\n", octocap_onnxruntime_version(),
              *octocap_openvino_version() ? octocap_openvino_version() : "not built in");
  if (argc > 1 && std::string(argv[1]) == "--runtimes") {  // that table alone
    const auto frames = read_frames(12);
    if (frames.empty()) return 1;
    runtimes(frames);
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "--crop-gap") {  // that table alone
    crop_gap();
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "--end-to-end") {  // that table alone (levers naming argv[2])
    end_to_end(argc > 2 ? argv[2] : "");
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "--accuracy") {  // that table alone (rows naming argv[2])
    accuracy(argc > 2 ? argv[2] : "");
    return 0;
  }
  const auto frames = read_frames(12);
  if (frames.empty()) {
    std::printf("videos missing in %s: run scripts/fetch-real-videos.sh\n", kVideos.c_str());
    return 1;
  }
  speed(frames);
  accuracy();
  crop_gap();
  return 0;
}
