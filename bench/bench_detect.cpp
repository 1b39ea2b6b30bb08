// 2D detection benchmark on real camera frames (Pose2Sim's demo videos, 1088x1920): ms per frame for 1, 4 and 8
// views, per path (per view, mosaic, crop) and model, with 1 and 2 ONNX Runtime threads; then each path's accuracy
// on the whole 4-camera take: keypoints solved, reprojection error, distance to Pose2Sim's own 3D.
// Run after scripts/fetch-models.sh and scripts/fetch-real-videos.sh (scripts/test.sh fetches both).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

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
};
const Path kPaths[] = {{"per-view lightning", OCTOCAP_DETECT_PER_VIEW, "movenet-lightning", 1},
                       {"per-view thunder", OCTOCAP_DETECT_PER_VIEW, "movenet-thunder", 1},
                       {"crop thunder", OCTOCAP_DETECT_CROP, "movenet-thunder", 1},
                       {"crop thunder, 2 views at once", OCTOCAP_DETECT_CROP, "movenet-thunder", 2},
                       {"crop thunder int8", OCTOCAP_DETECT_CROP, "movenet-thunder-int8", 1},
                       {"crop thunder int8, 2 views at once", OCTOCAP_DETECT_CROP, "movenet-thunder-int8", 2},
                       {"mosaic multipose", OCTOCAP_DETECT_MOSAIC, "movenet-multipose", 1}};

// threads 0 with parallel views: each view's inference gets cores / parallel views.
octocap_detector_config_t config_of(const Path& p, uint32_t threads) {
  octocap_detector_config_t c;
  octocap_detector_config_init(&c);
  std::snprintf(c.model, sizeof c.model, "%s", p.model);
  c.mode = p.mode;
  c.threads = p.parallel_views > 1 ? 0 : threads;
  c.parallel_views = p.parallel_views;
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

void accuracy() {
  octocap_calibration_t* calib = nullptr;
  if (octocap_calibration_load((kDemo + "/calibration/Calib_qualisys.toml").c_str(), &calib) != OCTOCAP_OK) {
    std::printf("no calibration: %s\n", octocap_last_error());
    return;
  }
  const auto frames = read_frames(100);
  std::printf("\n## Accuracy on the real 4-camera take (100 frames, triangulation, no filter, 2 threads)\n\n");
  std::printf("| path | keypoints solved | median reprojection px | median / mean distance to Pose2Sim 3D, mm | detect ms/frame |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const Path& p : kPaths) {
    octocap_session_config_t cfg;
    octocap_session_config_init(&cfg);
    cfg.layout = OCTOCAP_LAYOUT_COCO_17;
    cfg.filter = OCTOCAP_FILTER_NONE;
    octocap_session_t* s = nullptr;
    if (octocap_session_create(&cfg, calib, &s) != OCTOCAP_OK) continue;
    const octocap_detector_config_t detector = config_of(p, 2);
    if (octocap_session_set_detector(s, &detector) != OCTOCAP_OK) {
      std::printf("| %s | %s |\n", p.name, octocap_last_error());
      octocap_session_destroy(s);
      continue;
    }
    testing::Pose2SimReference score(kDemo + "/opensim/Balancing_for_IK.trc", OCTOCAP_LAYOUT_COCO_17);
    double detect_ms = 0;
    for (size_t f = 0; f < frames.size(); ++f) {
      const auto views = views_of(frames[f], 4);
      const octocap_result_t r = octocap_session_solve_images(s, views.data(), 4, static_cast<int64_t>(f) * 16667);
      octocap_detect_info_t info{};
      info.struct_size = sizeof info;
      octocap_session_detect_info(s, &info);
      detect_ms += info.total_ms;
      if (r != OCTOCAP_OK) continue;
      octocap_joint_t j[17];
      uint32_t n = 0;
      octocap_session_get_keypoints3d(s, j, 17, &n);
      score.add(f, j);
    }
    std::vector<double> dist;
    for (double d : score.distance_m) dist.push_back(1000 * d);
    const size_t solved = score.solved;
    const std::vector<double>& reproj = score.reprojection_px;
    double mean = 0;
    for (double d : dist) mean += d;
    std::printf("| %s | %.1f %% | %.2f | %.1f / %.1f | %.1f |\n", p.name, 100.0 * solved / (17.0 * frames.size()),
                median(reproj), median(dist), dist.empty() ? NAN : mean / dist.size(), detect_ms / frames.size());
    octocap_session_destroy(s);
  }
  octocap_calibration_destroy(calib);
}

}  // namespace

int main() {
  std::printf("# octocap 2D detection benchmark (ONNX Runtime %s)\n", octocap_onnxruntime_version());
  const auto frames = read_frames(12);
  if (frames.empty()) {
    std::printf("videos missing in %s: run scripts/fetch-real-videos.sh\n", kVideos.c_str());
    return 1;
  }
  speed(frames);
  accuracy();
  return 0;
}
