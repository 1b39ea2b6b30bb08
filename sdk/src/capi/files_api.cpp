// Recordings (OpenPose JSON folders) and motion writers (TRC / CSV).
#include <algorithm>
#include <cmath>
#include <limits>

#include "capi/boundary.h"
#include "capi/handles.h"
#include "io/sync_toml.h"
#include "solve/time_sync.h"

using namespace octocap::internal;

extern "C" {

octocap_result_t octocap_recording_open(const char* directory, octocap_layout_t layout_id,
                                        octocap_recording_t** out) {
  return capi::guard([&] {
    capi::require(directory, "directory");
    capi::require(out, "out");
    *out = nullptr;
    if (layout_id != OCTOCAP_LAYOUT_AUTO && octocap_layout_keypoint_count(layout_id) == 0)
      throw Error(Errc::invalid_argument, "unknown layout");
    auto rec = std::make_unique<OpenPoseRecording>(directory, static_cast<LayoutId>(layout_id));
    *out = capi::make_handle<octocap_recording_t>(std::move(rec));
  });
}

void octocap_recording_destroy(octocap_recording_t* rec) { capi::destroy_handle(rec); }

octocap_result_t octocap_recording_view_count(const octocap_recording_t* rec, uint32_t* out) {
  return capi::guard([&] {
    capi::checked(rec, "recording");
    capi::require(out, "out");
    *out = static_cast<uint32_t>(rec->recording->view_count());
  });
}

octocap_result_t octocap_recording_frame_count(const octocap_recording_t* rec, uint32_t* out) {
  return capi::guard([&] {
    capi::checked(rec, "recording");
    capi::require(out, "out");
    *out = static_cast<uint32_t>(rec->recording->frame_count());
  });
}

octocap_result_t octocap_recording_layout(const octocap_recording_t* rec, octocap_layout_t* out) {
  return capi::guard([&] {
    capi::checked(rec, "recording");
    capi::require(out, "out");
    *out = static_cast<octocap_layout_t>(rec->recording->layout());
  });
}

octocap_result_t octocap_recording_view_name(const octocap_recording_t* rec, uint32_t view, char* out,
                                             uint32_t capacity) {
  return capi::guard([&] {
    capi::checked(rec, "recording");
    capi::require(out, "out");
    if (view >= rec->recording->view_count()) throw Error(Errc::invalid_argument, "view index out of range");
    const std::string& name = rec->recording->view_name(view);
    if (capacity < name.size() + 1)
      throw Error(Errc::buffer_too_small, "view name needs " + std::to_string(name.size() + 1) + " bytes");
    capi::copy_name(out, capacity, name);
  });
}

octocap_result_t octocap_recording_read_frame(octocap_recording_t* rec, uint32_t frame,
                                              octocap_keypoint2d_t* keypoints, uint32_t capacity,
                                              uint32_t* keypoint_count, uint32_t* people_per_view,
                                              uint32_t view_count) {
  return capi::guard([&] {
    capi::checked(rec, "recording");
    capi::require(keypoint_count, "keypoint_count");
    const auto& r = *rec->recording;
    if (view_count != r.view_count())
      throw Error(Errc::camera_mismatch, "view_count is " + std::to_string(view_count) + ", the recording has " +
                                             std::to_string(r.view_count()) + " views");
    const auto people = r.read_frame(frame);
    size_t total = 0;
    for (const auto& v : people)
      for (const auto& p : v) total += p.size();
    *keypoint_count = static_cast<uint32_t>(total);
    if (people_per_view)
      for (size_t v = 0; v < people.size(); ++v) people_per_view[v] = static_cast<uint32_t>(people[v].size());
    if (!keypoints) return;
    capi::require(people_per_view, "people_per_view");
    if (capacity < total)
      throw Error(Errc::buffer_too_small, "frame " + std::to_string(frame) + " needs " + std::to_string(total) +
                                              " keypoints, capacity is " + std::to_string(capacity));
    size_t o = 0;
    for (const auto& v : people)
      for (const auto& p : v)
        for (const auto& k : p)
          keypoints[o++] = {static_cast<float>(k.x), static_cast<float>(k.y), static_cast<float>(k.confidence)};
  });
}

octocap_result_t octocap_motion_writer_create(const char* path, octocap_motion_format_t format,
                                              octocap_layout_t layout_id, octocap_up_axis_t up_axis, double rate_hz,
                                              octocap_motion_writer_t** out) {
  return capi::guard([&] {
    capi::require(path, "path");
    capi::require(out, "out");
    *out = nullptr;
    if (format != OCTOCAP_MOTION_TRC && format != OCTOCAP_MOTION_CSV && format != OCTOCAP_MOTION_BVH &&
        format != OCTOCAP_MOTION_CSV_PEOPLE)
      throw Error(Errc::invalid_argument, "unknown motion format");
    if (octocap_layout_keypoint_count(layout_id) == 0)
      throw Error(Errc::invalid_argument, "layout must be a concrete layout (not AUTO)");
    auto writer = std::make_unique<MotionWriter>(path, static_cast<MotionFormat>(format),
                                                 static_cast<LayoutId>(layout_id), up_axis == OCTOCAP_UP_Z, rate_hz);
    *out = capi::make_handle<octocap_motion_writer_t>(std::move(writer));
  });
}

octocap_result_t octocap_motion_writer_add(octocap_motion_writer_t* w, const octocap_frame_t* frame, uint32_t person) {
  return capi::guard([&] {
    MotionWriter& writer = *capi::checked(w, "motion writer")->writer;
    writer.add(*capi::checked(frame, "frame")->frame, person);
  });
}

octocap_result_t octocap_motion_writer_add_frame(octocap_motion_writer_t* w, const octocap_session_t* s) {
  return capi::guard([&] {
    MotionWriter& writer = *capi::checked(w, "motion writer")->writer;
    const Session& session = *capi::checked(s, "session")->session;
    if (!session.has_result()) throw Error(Errc::no_result, "the session has not solved a frame yet");
    writer.add(session.result(), 0);
  });
}

octocap_result_t octocap_motion_writer_add_keypoints(octocap_motion_writer_t* w, const octocap_joint_t* keypoints,
                                                     uint32_t count) {
  return capi::guard([&] {
    MotionWriter& writer = *capi::checked(w, "motion writer")->writer;
    capi::require(keypoints, "keypoints");
    std::vector<Eigen::Vector3d> points(count, Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
    for (uint32_t k = 0; k < count; ++k)
      if (keypoints[k].valid)
        points[k] = Eigen::Vector3d(keypoints[k].position[0], keypoints[k].position[1], keypoints[k].position[2]);
    writer.add_keypoints(points);
  });
}

octocap_result_t octocap_motion_writer_add_empty_frame(octocap_motion_writer_t* w) {
  return capi::guard([&] { capi::checked(w, "motion writer")->writer->add_empty(); });
}

octocap_result_t octocap_motion_writer_add_empty_frame_at(octocap_motion_writer_t* w, int64_t timestamp_us) {
  return capi::guard([&] { capi::checked(w, "motion writer")->writer->add_empty(timestamp_us); });
}

octocap_result_t octocap_motion_writer_set_journal(octocap_motion_writer_t* w, const char* journal_path) {
  return capi::guard([&] {
    MotionWriter& writer = *capi::checked(w, "motion writer")->writer;
    capi::require(journal_path, "journal_path");
    writer.journal_to(journal_path);
  });
}

octocap_result_t octocap_motion_writer_close(octocap_motion_writer_t* w) {
  if (!w) return OCTOCAP_OK;
  const octocap_result_t r = capi::guard([&] { capi::checked(w, "motion writer")->writer->close(); });
  if (r != OCTOCAP_ERROR_INVALID_HANDLE) capi::destroy_handle(w);
  return r;
}

void octocap_motion_writer_discard(octocap_motion_writer_t* w) { capi::destroy_handle(w); }

}  // extern "C"

// Sync of unsynchronised cameras: estimate, apply to a recording, and the TOML on disk.
extern "C" {

octocap_result_t octocap_recording_estimate_sync(const octocap_recording_t* rec, const octocap_calibration_t* calib,
                                                 double max_offset_frames, double* offsets_frames, float* residual_px,
                                                 uint32_t count) {
  return capi::guard([&] {
    capi::checked(rec, "recording");
    capi::checked(calib, "calibration");
    capi::require(offsets_frames, "offsets_frames");
    if (count != calib->cameras.size())
      throw Error(Errc::camera_mismatch, "count is " + std::to_string(count) + ", the calibration has " +
                                             std::to_string(calib->cameras.size()) + " cameras");
    SyncOptions o;
    o.max_offset_frames = max_offset_frames;
    const SyncEstimate e = estimate_recording_offsets(calib->cameras, *rec->recording, o);
    for (uint32_t c = 0; c < count; ++c) {
      offsets_frames[c] = e.offset_frames[c];
      if (residual_px) residual_px[c] = static_cast<float>(e.residual_px[c]);
    }
  });
}

octocap_result_t octocap_recording_set_sync(octocap_recording_t* rec, const double* offsets_frames, uint32_t count) {
  return capi::guard([&] {
    capi::checked(rec, "recording");
    if (!offsets_frames) return rec->recording->set_time_offsets({});
    rec->recording->set_time_offsets(std::vector<double>(offsets_frames, offsets_frames + count));
  });
}

octocap_result_t octocap_sync_save(const char* path, double rate_hz, const octocap_calibration_t* calib,
                                   const double* offsets_frames, uint32_t count) {
  return capi::guard([&] {
    capi::require(path, "path");
    capi::checked(calib, "calibration");
    capi::require(offsets_frames, "offsets_frames");
    if (count != calib->cameras.size()) throw Error(Errc::camera_mismatch, "one offset per calibrated camera");
    SyncFile s;
    s.rate_hz = rate_hz;
    for (uint32_t c = 0; c < count; ++c) {
      s.cameras.push_back(calib->cameras[c].name);
      s.offsets_frames.push_back(offsets_frames[c]);
    }
    write_sync_toml(path, s);
  });
}

octocap_result_t octocap_sync_load(const char* path, const octocap_calibration_t* calib, double* offsets_frames,
                                   uint32_t count, double* rate_hz) {
  return capi::guard([&] {
    capi::require(path, "path");
    capi::checked(calib, "calibration");
    capi::require(offsets_frames, "offsets_frames");
    if (count != calib->cameras.size()) throw Error(Errc::camera_mismatch, "one offset per calibrated camera");
    const SyncFile s = read_sync_toml(path);
    for (uint32_t c = 0; c < count; ++c) {
      const auto it = std::find(s.cameras.begin(), s.cameras.end(), calib->cameras[c].name);
      if (it == s.cameras.end())
        throw Error(Errc::parse, std::string(path) + ": no offset for camera " + calib->cameras[c].name);
      offsets_frames[c] = s.offsets_frames[static_cast<size_t>(it - s.cameras.begin())];
    }
    if (rate_hz) *rate_hz = s.rate_hz;
  });
}

}  // extern "C"
