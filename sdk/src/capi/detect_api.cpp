// 2D detection entry points: the stand-alone detector, and the session's solve from images.
#include <cstddef>
#include <cstring>

#include "capi/boundary.h"
#include "capi/detect_c.h"
#include "capi/frame_queries.h"
#include "capi/handles.h"
#include "capi/struct_versions.h"
#include "detect/ort_model.h"
#include "detect/ov_model.h"

using namespace octocap::internal;

namespace octocap::internal::capi {

DetectorConfig detector_config(const octocap_detector_config_t& given) {
  check_size(given.struct_size, kDetectorConfigSizes, "octocap_detector_config_t");
  octocap_detector_config_t defaults;
  octocap_detector_config_init(&defaults);
  const octocap_detector_config_t c = widen(given, defaults);
  DetectorConfig d;
  d.model = c_text(c.model, sizeof c.model, "detector model path");
  // Enums and counts cast as given (every core enum is int-based, so any value is defined): the mapping judges
  // nothing, DetectorConfig::validate() does, where a config is used (the Detector, a session, a capture node).
  d.mode = static_cast<DetectMode>(c.mode);
  d.pick = static_cast<PersonPick>(c.person_pick);
  d.threads = static_cast<int>(std::min<uint32_t>(c.threads, 1u << 20));
  d.mosaic_tile = static_cast<int>(std::min<uint32_t>(c.mosaic_tile_px, 1u << 20));
  d.max_people = c.max_people;
  d.parallel_views = static_cast<int>(std::min<uint32_t>(c.parallel_views, 1u << 20));
  d.min_confidence = c.min_confidence;
  d.views_per_frame = static_cast<int>(std::min<uint32_t>(c.views_per_frame, 1u << 20));
  d.device = static_cast<Device>(c.device);
  d.runtime = static_cast<Runtime>(c.runtime);
  d.precision = static_cast<Precision>(c.precision);
  return d;
}

// DetectorConfig -> the C struct: octocap_detector_config_defaults() converts a default-constructed DetectorConfig,
// so each default has one home (detect/detector.h).
octocap_detector_config_t c_detector_config(const DetectorConfig& d) {
  octocap_detector_config_t c{};
  c.struct_size = sizeof c;
  copy_name(c.model, sizeof c.model, d.model);
  c.mode = static_cast<octocap_detect_mode_t>(d.mode);
  c.person_pick = static_cast<octocap_person_pick_t>(d.pick);
  c.threads = static_cast<uint32_t>(d.threads);
  c.mosaic_tile_px = static_cast<uint32_t>(d.mosaic_tile);
  c.max_people = static_cast<uint32_t>(d.max_people);
  c.min_confidence = static_cast<float>(d.min_confidence);
  c.parallel_views = static_cast<uint32_t>(d.parallel_views);
  c.views_per_frame = static_cast<uint32_t>(d.views_per_frame);
  c.device = static_cast<octocap_device_t>(d.device);
  c.runtime = static_cast<octocap_runtime_t>(d.runtime);
  c.precision = static_cast<octocap_precision_t>(d.precision);
  return c;
}

std::vector<ImageView> image_views(const octocap_image_t* images, uint32_t count) {
  if (count == 0) throw Error(Errc::invalid_argument, "no images (count is 0)");
  require(images, "images");
  std::vector<ImageView> views(count);
  for (uint32_t i = 0; i < count; ++i) {
    const octocap_image_t& im = images[i];
    if (im.format < OCTOCAP_PIXELS_RGB8 || im.format > OCTOCAP_PIXELS_RGBA8)
      throw Error(Errc::invalid_argument, "image " + std::to_string(i) + ": unknown pixel format " + std::to_string(im.format));
    if (im.width > 16384 || im.height > 16384 || im.stride_bytes > (1u << 20))
      throw Error(Errc::invalid_argument, "image " + std::to_string(i) + ": size or stride out of range");
    views[i] = {im.pixels, static_cast<int>(im.width), static_cast<int>(im.height), static_cast<int>(im.stride_bytes),
                static_cast<PixelFormat>(im.format)};
    if (!absent(views[i])) validate_image(views[i], ("image " + std::to_string(i)).c_str());
  }
  return views;
}

void fill_detect_info(const Detector& detector, octocap_detect_info_t* out) {
  require(out, "out");
  // 1.2 callers' struct ends before `mode`, 1.3 and 1.4 callers' before `views_tracked`, 1.5-1.8 callers' before
  // `runtime`.
  const uint32_t size12 = static_cast<uint32_t>(offsetof(octocap_detect_info_t, mode));
  const uint32_t size14 = static_cast<uint32_t>(offsetof(octocap_detect_info_t, views_tracked));
  const uint32_t size18 = static_cast<uint32_t>(offsetof(octocap_detect_info_t, runtime));
  if (out->struct_size != sizeof(octocap_detect_info_t) && out->struct_size != size12 && out->struct_size != size14 &&
      out->struct_size != size18)
    throw Error(Errc::struct_size, "octocap_detect_info_t.struct_size must be " + std::to_string(sizeof(octocap_detect_info_t)));
  const DetectTimings& t = detector.timings();
  out->total_ms = static_cast<float>(t.total_ms);
  out->preprocess_ms = static_cast<float>(t.preprocess_ms);
  out->inference_ms = static_cast<float>(t.inference_ms);
  out->inferences = static_cast<uint32_t>(t.inferences);
  out->layout = static_cast<octocap_layout_t>(detector.card().layout);
  out->keypoint_count = static_cast<uint32_t>(layout(detector.card().layout).keypoints.size());
  copy_name(out->model, sizeof out->model, detector.card().name);
  if (out->struct_size >= size14) out->mode = static_cast<octocap_detect_mode_t>(detector.config().mode);
  if (out->struct_size >= size18) {
    out->views_tracked = static_cast<uint32_t>(t.views_tracked);
    out->track_ms = static_cast<float>(t.track_ms);
    out->device = static_cast<octocap_device_t>(detector.device());
  }
  if (out->struct_size == sizeof(octocap_detect_info_t)) {
    out->runtime = static_cast<octocap_runtime_t>(detector.runtime());
    out->precision = static_cast<octocap_precision_t>(detector.precision());
  }
}

}  // namespace octocap::internal::capi

namespace {

void copy_keypoints(const Person2D& p, octocap_keypoint2d_t* out) {
  for (size_t k = 0; k < p.size(); ++k)
    out[k] = {static_cast<float>(p[k].x), static_cast<float>(p[k].y), static_cast<float>(p[k].confidence)};
}

const std::vector<DetectedPerson>& view_people(const std::vector<std::vector<DetectedPerson>>& all, uint32_t view) {
  if (view >= all.size())
    throw Error(Errc::invalid_argument, "view " + std::to_string(view) + " out of range (" + std::to_string(all.size()) +
                                            " views in the last detection)");
  return all[view];
}

}  // namespace

extern "C" {

octocap_result_t octocap_detector_config_defaults(octocap_detector_config_t* c, uint32_t struct_size) {
  return capi::guard([&] {
    capi::require(c, "cfg");
    capi::check_size(struct_size, capi::kDetectorConfigSizes, "octocap_detector_config_t");
    octocap_detector_config_t d = capi::c_detector_config(DetectorConfig{});
    capi::write_defaults(c, struct_size, d);
  });
}

octocap_result_t octocap_detector_create(const octocap_detector_config_t* cfg, octocap_detector_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(cfg, "cfg");
    auto detector = std::make_unique<Detector>(capi::detector_config(*cfg));
    *out = capi::make_handle<octocap_detector_t>(std::move(detector));
  });
}

void octocap_detector_destroy(octocap_detector_t* d) { capi::destroy_handle(d); }

octocap_result_t octocap_detector_run(octocap_detector_t* d, const octocap_image_t* images, uint32_t count) {
  return capi::guard([&] {
    capi::checked(d, "detector");
    d->people.clear();
    d->people = d->detector->detect(capi::image_views(images, count));
  });
}

octocap_result_t octocap_detector_people(const octocap_detector_t* d, uint32_t view, uint32_t* count) {
  return capi::guard([&] {
    capi::checked(d, "detector");
    capi::require(count, "count");
    *count = static_cast<uint32_t>(view_people(d->people, view).size());
  });
}

octocap_result_t octocap_detector_keypoints(const octocap_detector_t* d, uint32_t view, uint32_t person,
                                            octocap_keypoint2d_t* out, uint32_t capacity, uint32_t* count) {
  return capi::guard([&] {
    capi::checked(d, "detector");
    const auto& people = view_people(d->people, view);
    if (person >= people.size())
      throw Error(Errc::invalid_argument, "person " + std::to_string(person) + " out of range (" +
                                              std::to_string(people.size()) + " in view " + std::to_string(view) + ")");
    const Person2D& p = people[person].keypoints;
    capi::fill_array(static_cast<uint32_t>(p.size()), out, capacity, count, [&] { copy_keypoints(p, out); });
  });
}

octocap_result_t octocap_detector_info(const octocap_detector_t* d, octocap_detect_info_t* out) {
  return capi::guard([&] {
    capi::checked(d, "detector");
    capi::fill_detect_info(*d->detector, out);
  });
}

octocap_result_t octocap_model_layout(const char* model, octocap_layout_t* layout) {
  return capi::guard([&] {
    capi::require(model, "model");
    capi::require(layout, "layout");
    const ModelCard card = read_model_card(model_card_path(resolve_model_path(model, DetectMode::crop)));
    *layout = static_cast<octocap_layout_t>(card.layout);
  });
}

const char* octocap_onnxruntime_version(void) {
  static thread_local std::string version;
  try {
    version = onnxruntime_version();
  } catch (...) {
    version.clear();
  }
  return version.c_str();
}

const char* octocap_openvino_version(void) {
  static thread_local std::string version;
  try {
    version = openvino_version();
  } catch (...) {
    version.clear();
  }
  return version.c_str();
}

octocap_result_t octocap_session_solve_images(octocap_session_t* s, const octocap_image_t* images,
                                              uint32_t view_count, int64_t timestamp_us) {
  bool solved = false;
  const octocap_result_t r = capi::guard([&] {
    capi::checked(s, "session");
    solved = s->session->solve_images(capi::image_views(images, view_count), timestamp_us);
  });
  return capi::status_unless(r, solved, OCTOCAP_STATUS_NO_PERSON);
}

octocap_result_t octocap_session_set_detector(octocap_session_t* s, const octocap_detector_config_t* cfg) {
  return capi::guard([&] {
    capi::checked(s, "session");
    capi::require(cfg, "cfg");
    s->session->set_detector(capi::detector_config(*cfg));
  });
}

octocap_result_t octocap_session_detections(const octocap_session_t* s, uint32_t view, octocap_keypoint2d_t* out,
                                            uint32_t capacity, uint32_t* count) {
  return capi::guard([&] {
    capi::checked(s, "session");
    if (!s->session->detector()) throw Error(Errc::no_result, "no frame has been solved from images yet");
    const auto& people = view_people(s->session->detections(), view);
    size_t needed = 0;
    for (const auto& p : people) needed += p.keypoints.size();
    capi::fill_array(static_cast<uint32_t>(needed), out, capacity, count, [&] {
      size_t at = 0;
      for (const auto& p : people) {
        copy_keypoints(p.keypoints, out + at);
        at += p.keypoints.size();
      }
    });
  });
}

octocap_result_t octocap_session_detect_info(const octocap_session_t* s, octocap_detect_info_t* out) {
  return capi::guard([&] {
    capi::checked(s, "session");
    if (!s->session->detector()) throw Error(Errc::no_result, "no frame has been solved from images yet");
    capi::fill_detect_info(*s->session->detector(), out);
  });
}

}  // extern "C"
