#include "detect_command.h"

#include "command_main.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <vector>

#include "debug_draw.h"
#include "octocap/octocap.hpp"

namespace fs = std::filesystem;

namespace {


// OpenPose's own JSON (version 1.3), one file per camera and frame, as octocap solve --keypoints and Pose2Sim read.
void write_openpose(const fs::path& path, const std::vector<std::vector<octocap_keypoint2d_t>>& people) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << "{\"version\":1.3,\"people\":[";
  for (size_t p = 0; p < people.size(); ++p) {
    out << (p ? "," : "") << "{\"person_id\":[-1],\"pose_keypoints_2d\":[";
    for (size_t k = 0; k < people[p].size(); ++k) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%s%.2f,%.2f,%.4f", k ? "," : "", people[p][k].x, people[p][k].y,
                    people[p][k].confidence);
      out << buf;
    }
    out << "]}";
  }
  out << "]}\n";
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

int detect(const DetectOptions& o) {
  if (o.images.empty() || o.output.empty())
    throw std::runtime_error("--images and --output are required (or --live, a capture node)");
  octocap::TakeReader source(o.images);
  const octocap_detector_config_t cfg = o.detector.config();
  octocap::Detector detector(cfg);
  const size_t frames = o.max_frames ? std::min<size_t>(o.max_frames, source.frame_count()) : source.frame_count();
  std::vector<std::string> names;
  for (uint32_t c = 0; c < source.camera_count(); ++c) names.push_back(source.camera_name(c));
  for (const auto& n : names) fs::create_directories(fs::path(o.output) / (n + "_json"));
  if (!o.debug_images.empty()) fs::create_directories(o.debug_images);
  octocap_detect_info_t info{};
  double total_ms = 0, inference_ms = 0;
  size_t found = 0;
  for (size_t f = 0; f < frames; ++f) {
    const std::vector<octocap_image_t>& views = source.read(static_cast<uint32_t>(f));
    detector.run(views.data(), static_cast<uint32_t>(views.size()));
    info = detector.info();
    total_ms += info.total_ms;
    inference_ms += info.inference_ms;
    for (size_t v = 0; v < views.size(); ++v) {
      const uint32_t count = detector.people(static_cast<uint32_t>(v));
      std::vector<std::vector<octocap_keypoint2d_t>> people;
      std::vector<octocap_keypoint2d_t> flat;
      for (uint32_t p = 0; p < count; ++p) {
        people.push_back(detector.keypoints(static_cast<uint32_t>(v), p));
        flat.insert(flat.end(), people.back().begin(), people.back().end());
      }
      found += count > 0;
      char file[160];
      std::snprintf(file, sizeof file, "%s_%012zu_keypoints.json", names[v].c_str(), f);
      write_openpose(fs::path(o.output) / (names[v] + "_json") / file, people);
      if (!o.debug_images.empty()) {
        cv::Mat picture = drawable_copy(views[v]);
        draw_detections(picture, flat, info.keypoint_count, info.layout, 0.3f);
        cv::imwrite(debug_image_path(o.debug_images, names[v], f), picture);
      }
    }
    if (!o.quiet && frames >= 20 && (f + 1) % std::max<size_t>(1, frames / 10) == 0)
      std::fprintf(stderr, "\r  frame %zu / %zu", f + 1, frames);
  }
  if (!o.quiet && frames >= 20) std::fprintf(stderr, "\n");
  std::printf("octocap detect: %zu frames x %zu cameras, model %s (%s), mode %s, %s\n", frames, names.size(),
              info.model, octocap_layout_name(info.layout), o.detector.mode.c_str(), runtime_description(info).c_str());
  std::printf("  views with a person:  %zu / %zu\n", found, frames * names.size());
  std::printf("  detection time:       %.1f ms/frame (inference %.1f ms), %.1f frames/s\n",
              frames ? total_ms / frames : 0.0, frames ? inference_ms / frames : 0.0,
              total_ms > 0 ? frames * 1000.0 / total_ms : 0.0);
  std::printf("  wrote %s/<camera>_json/\n", o.output.c_str());
  return 0;
}

}  // namespace

octocap_detector_config_t DetectorOptions::config() const {
  octocap_detector_config_t c;
  octocap_detector_config_init(&c);
  if (model.size() >= sizeof c.model) throw std::runtime_error("--model path is too long");
  std::snprintf(c.model, sizeof c.model, "%s", model.c_str());
  c.mode = mode == "mosaic" ? OCTOCAP_DETECT_MOSAIC : mode == "crop" ? OCTOCAP_DETECT_CROP : OCTOCAP_DETECT_PER_VIEW;
  c.person_pick = pick == "largest"          ? OCTOCAP_PICK_LARGEST
                  : pick == "most-confident" ? OCTOCAP_PICK_MOST_CONFIDENT
                  : pick == "nearest"        ? OCTOCAP_PICK_NEAREST_PREVIOUS
                                             : OCTOCAP_PICK_ALL;
  c.threads = threads;
  c.mosaic_tile_px = mosaic_tile;
  c.max_people = max_people;
  c.parallel_views = parallel_views;
  c.views_per_frame = views_per_frame;
  c.device = device == "cuda" ? OCTOCAP_DEVICE_CUDA : device == "auto" ? OCTOCAP_DEVICE_AUTO : OCTOCAP_DEVICE_CPU;
  c.runtime = runtime == "openvino" ? OCTOCAP_RUNTIME_OPENVINO : runtime == "onnxruntime" ? OCTOCAP_RUNTIME_ONNXRUNTIME
                                                                                          : OCTOCAP_RUNTIME_AUTO;
  c.precision = precision == "f32" ? OCTOCAP_PRECISION_F32 : precision == "reduced" ? OCTOCAP_PRECISION_REDUCED
                                                                                    : OCTOCAP_PRECISION_AUTO;
  return c;
}

std::string runtime_description(const octocap_detect_info_t& info) {
  const bool ov = info.runtime == OCTOCAP_RUNTIME_OPENVINO;
  std::string s = ov ? std::string("OpenVINO ") + octocap_openvino_version()
                     : std::string("ONNX Runtime ") + octocap_onnxruntime_version();
  s += info.precision == OCTOCAP_PRECISION_REDUCED ? " (bf16" : " (f32";
  s += info.device == OCTOCAP_DEVICE_CUDA ? ", GPU)" : ")";
  return s;
}

cv::Mat drawable_copy(const octocap_image_t& bgr) {
  const cv::Mat borrowed(static_cast<int>(bgr.height), static_cast<int>(bgr.width), CV_8UC3,
                         const_cast<uint8_t*>(bgr.pixels), bgr.stride_bytes);
  return borrowed.clone();
}

std::string debug_image_path(const std::string& dir, const std::string& camera, size_t frame) {
  char name[160];
  std::snprintf(name, sizeof name, "%s_frame_%06zu.png", camera.c_str(), frame);
  return (fs::path(dir) / name).string();
}

int run_detect(const DetectOptions& options) {
  return options.live ? run_node(options) : run_reporting_errors("detect", options, detect);
}
