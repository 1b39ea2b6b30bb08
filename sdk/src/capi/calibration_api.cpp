// Calibration handles: load, save, build from cameras, inspect, project.
#include <algorithm>
#include <cstring>
#include <iterator>

#include "capi/boundary.h"
#include "capi/camera_c.h"
#include "capi/handles.h"
#include "io/calibration_toml.h"
#include "io/calibration_yaml.h"

using namespace octocap::internal;

namespace {

Camera from_c(const octocap_camera_t& c, uint32_t index) {
  CameraValues v;
  v.name.assign(c.name, strnlen(c.name, sizeof c.name));
  v.fisheye = c.fisheye != 0;
  v.width = c.width, v.height = c.height;
  for (int i = 0; i < 9; ++i) v.matrix(i / 3, i % 3) = c.matrix[i];
  std::copy(std::begin(c.distortion), std::end(c.distortion), v.distortion.begin());
  v.rotation = {c.rotation[0], c.rotation[1], c.rotation[2]};
  v.translation = {c.translation[0], c.translation[1], c.translation[2]};
  if (const std::string why = implausible_camera(v); !why.empty())
    throw Error(Errc::invalid_argument, "camera " + std::to_string(index) + ": " + why);
  return camera_of(v);
}

}  // namespace

void capi::camera_to_c(const Camera& cam, octocap_camera_t& c) {
  capi::copy_name(c.name, sizeof c.name, cam.name);
  c.width = static_cast<uint32_t>(cam.width);
  c.height = static_cast<uint32_t>(cam.height);
  for (int i = 0; i < 9; ++i) c.matrix[i] = cam.K(i / 3, i % 3);
  for (int i = 0; i < 5; ++i) c.distortion[i] = cam.dist[i];
  c.fisheye = cam.fisheye ? 1 : 0;
  const Eigen::Vector3d r = matrix_to_rodrigues(cam.R);
  for (int i = 0; i < 3; ++i) {
    c.rotation[i] = r[i];
    c.translation[i] = cam.t[i];
  }
}

namespace {

const Camera& camera_at(const octocap_calibration_t* calib, uint32_t index) {
  capi::checked(calib, "calibration");
  if (index >= calib->cameras.size())
    throw Error(Errc::invalid_argument, "camera index " + std::to_string(index) + " out of range (" +
                                            std::to_string(calib->cameras.size()) + " cameras)");
  return calib->cameras[index];
}

}  // namespace

extern "C" {

octocap_result_t octocap_calibration_load(const char* path, octocap_calibration_t** out) {
  return capi::guard([&] {
    capi::require(path, "path");
    capi::require(out, "out");
    *out = nullptr;
    Calibration c = read_calibration_toml(path);
    *out = capi::make_handle<octocap_calibration_t>(std::move(c));
  });
}

octocap_result_t octocap_calibration_create(const octocap_camera_t* cameras, uint32_t count,
                                            octocap_calibration_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(cameras, "cameras");
    if (count == 0) throw Error(Errc::invalid_argument, "count is 0");
    Calibration c;
    for (uint32_t i = 0; i < count; ++i) c.push_back(from_c(cameras[i], i));
    *out = capi::make_handle<octocap_calibration_t>(std::move(c));
  });
}

octocap_result_t octocap_calibration_save(const octocap_calibration_t* calib, const char* path) {
  return capi::guard([&] {
    capi::checked(calib, "calibration");
    capi::require(path, "path");
    write_calibration_toml(calib->cameras, path);
  });
}

octocap_result_t octocap_calibration_save_opencv_yaml(const octocap_calibration_t* calib, const char* path) {
  return capi::guard([&] {
    capi::checked(calib, "calibration");
    capi::require(path, "path");
    write_calibration_opencv_yaml(calib->cameras, path);
  });
}

octocap_result_t octocap_calibration_camera_count(const octocap_calibration_t* calib, uint32_t* out) {
  return capi::guard([&] {
    capi::checked(calib, "calibration");
    capi::require(out, "out");
    *out = static_cast<uint32_t>(calib->cameras.size());
  });
}

octocap_result_t octocap_calibration_get_camera(const octocap_calibration_t* calib, uint32_t index,
                                                octocap_camera_t* out) {
  return capi::guard([&] {
    const Camera& cam = camera_at(calib, index);
    capi::require(out, "out");
    capi::camera_to_c(cam, *out);
  });
}

octocap_result_t octocap_calibration_project(const octocap_calibration_t* calib, uint32_t index,
                                             const double world[3], double pixel_out[2]) {
  return capi::guard([&] {
    const Camera& cam = camera_at(calib, index);
    capi::require(world, "world");
    capi::require(pixel_out, "pixel_out");
    for (int k = 0; k < 3; ++k) capi::require_finite(world[k], "world");
    const Eigen::Vector2d p = cam.project({world[0], world[1], world[2]});
    if (!p.allFinite()) throw Error(Errc::invalid_argument, "the point is behind camera " + cam.name);
    pixel_out[0] = p.x();
    pixel_out[1] = p.y();
  });
}

void octocap_calibration_destroy(octocap_calibration_t* calib) { capi::destroy_handle(calib); }

}  // extern "C"
