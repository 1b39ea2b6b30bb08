// Calibration solving: intrinsics from board images, extrinsics from a person's keypoints.
#include <cmath>
#include <cstring>

#include "calib/board_extrinsics.h"
#include "calib/extrinsics.h"
#include "calib/intrinsics.h"
#include "capi/boundary.h"
#include "capi/struct_versions.h"
#include "capi/camera_c.h"
#include "capi/handles.h"

using namespace octocap::internal;

extern "C" {

octocap_result_t octocap_calibration_solve_intrinsics(const char* images_dir, const char* board, octocap_camera_t* out,
                                                      float* rms_px, uint32_t* images_used, uint32_t* images_rejected,
                                                      const char* overlay_png) {
  return capi::guard([&] {
    capi::require(images_dir, "images_dir");
    capi::require(board, "board");
    capi::require(out, "out");
    IntrinsicsReport rep;
    const Camera cam = calibrate_intrinsics(images_dir, parse_board(board), &rep, overlay_png ? overlay_png : "");
    capi::camera_to_c(cam, *out);
    if (rms_px) *rms_px = static_cast<float>(rep.rms_px);
    if (images_used) *images_used = static_cast<uint32_t>(rep.used.size());
    if (images_rejected) *images_rejected = static_cast<uint32_t>(rep.rejected.size());
  });
}

octocap_result_t octocap_extrinsics_options_defaults(octocap_extrinsics_options_t* o, uint32_t struct_size) {
  return capi::guard([&] {
    capi::require(o, "opt");
    capi::check_size(struct_size, capi::kExtrinsicsOptionsSizes, "octocap_extrinsics_options_t");
    octocap_extrinsics_options_t d{};
    d.distance_camera_a = -1;
    d.distance_camera_b = -1;
    d.min_confidence = 0.4f;
    d.max_frames = 1500;
    d.up_axis = OCTOCAP_UP_Y;
    capi::write_defaults(o, struct_size, d);
  });
}

namespace {

void to_c_report(const ExtrinsicsReport& rep, octocap_calibration_report_t* report) {
  if (!report) return;
  *report = octocap_calibration_report_t{};
  report->camera_count = static_cast<uint32_t>(rep.rms_px.size());
  for (size_t v = 0; v < rep.rms_px.size(); ++v) {
    report->rms_px[v] = static_cast<float>(rep.rms_px[v]);
    report->observations[v] = static_cast<uint32_t>(rep.observations[v]);
  }
  report->points = static_cast<uint32_t>(rep.points);
  report->iterations = static_cast<uint32_t>(rep.iterations);
  report->initial_rms_px = static_cast<float>(rep.initial_rms_px);
  report->final_rms_px = static_cast<float>(rep.final_rms_px);
}

// The caller's options (of any released size) as today's struct, checked.
octocap_extrinsics_options_t check_options(const octocap_extrinsics_options_t* given,
                                           const octocap_calibration_t* intrinsics) {
  capi::require(given, "opt");
  capi::check_size(given->struct_size, capi::kExtrinsicsOptionsSizes, "octocap_extrinsics_options_t");
  octocap_extrinsics_options_t defaults;
  octocap_extrinsics_options_init(&defaults);
  const octocap_extrinsics_options_t options = capi::widen(*given, defaults);
  const octocap_extrinsics_options_t* opt = &options;
  for (float v : {opt->person_height_m, opt->camera_distance_m, opt->min_confidence})
    capi::require_finite(v, "an extrinsics option");
  if (opt->up_axis != OCTOCAP_UP_Y && opt->up_axis != OCTOCAP_UP_Z && opt->up_axis != OCTOCAP_UP_AUTO)
    throw Error(Errc::invalid_argument, "up_axis must be Y or Z");
  if (intrinsics->cameras.size() > 64) throw Error(Errc::invalid_argument, "at most 64 cameras");
  return options;
}

}  // namespace

octocap_result_t octocap_calibration_solve_extrinsics_boards(const octocap_calibration_t* intrinsics,
                                                             const char* images_dir, const char* board,
                                                             const octocap_extrinsics_options_t* opt,
                                                             octocap_calibration_t** out,
                                                             octocap_calibration_report_t* report) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::checked(intrinsics, "calibration");
    capi::require(images_dir, "images_dir");
    capi::require(board, "board");
    const octocap_extrinsics_options_t checked_options = check_options(opt, intrinsics);
    opt = &checked_options;
    const BoardSpec spec = parse_board(board);
    const BoardViews views = detect_board_views(images_dir, intrinsics->cameras.size(), spec);
    ExtrinsicsReport rep;
    Calibration c = calibrate_extrinsics_from_boards(intrinsics->cameras, views, spec, opt->up_axis == OCTOCAP_UP_Z, &rep);
    *out = capi::make_handle<octocap_calibration_t>(std::move(c));
    to_c_report(rep, report);
  });
}

octocap_result_t octocap_calibration_solve_extrinsics(const octocap_calibration_t* intrinsics, octocap_recording_t* rec,
                                                      const octocap_extrinsics_options_t* opt,
                                                      octocap_calibration_t** out,
                                                      octocap_calibration_report_t* report) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::checked(intrinsics, "calibration");
    capi::checked(rec, "recording");
    const octocap_extrinsics_options_t checked_options = check_options(opt, intrinsics);
    opt = &checked_options;
    const auto& r = *rec->recording;
    if (r.view_count() != intrinsics->cameras.size())
      throw Error(Errc::camera_mismatch, "the recording has " + std::to_string(r.view_count()) +
                                             " camera folders, the calibration " +
                                             std::to_string(intrinsics->cameras.size()) + " cameras");
    std::vector<std::vector<std::vector<Person2D>>> frames;
    for (size_t f = 0; f < r.frame_count(); ++f) frames.push_back(r.read_frame(f));
    ExtrinsicsOptions o;
    o.person_height_m = opt->person_height_m;
    o.camera_distance_m = opt->camera_distance_m;
    o.distance_camera_a = opt->distance_camera_a;
    o.distance_camera_b = opt->distance_camera_b;
    o.min_confidence = opt->min_confidence;
    o.max_frames = std::max<uint32_t>(opt->max_frames, 10);
    o.z_up = opt->up_axis == OCTOCAP_UP_Z;
    o.refine = opt->refine != 0;
    ExtrinsicsReport rep;
    Calibration c = calibrate_extrinsics(intrinsics->cameras, frames, r.layout(), o, &rep);
    *out = capi::make_handle<octocap_calibration_t>(std::move(c));
    to_c_report(rep, report);
  });
}

}  // extern "C"
