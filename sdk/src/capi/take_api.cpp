// Recorded takes through the C ABI: capture/take_reader.h's pictures handed out as borrowed images.
#include <algorithm>
#include <cstdint>

#include "capi/boundary.h"
#include "capi/handles.h"

using namespace octocap::internal;

extern "C" {

octocap_result_t octocap_take_reader_open(const char* folder, octocap_take_reader_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(folder, "folder");
    auto reader = std::make_unique<TakeReader>(folder);
    *out = capi::make_handle<octocap_take_reader_t>(std::move(reader));
  });
}

void octocap_take_reader_destroy(octocap_take_reader_t* reader) { capi::destroy_handle(reader); }

octocap_result_t octocap_take_reader_info(const octocap_take_reader_t* r, octocap_take_info_t* out) {
  return capi::guard([&] {
    capi::checked(r, "take reader");
    capi::require(out, "out");
    if (out->struct_size != sizeof(octocap_take_info_t))
      throw Error(Errc::struct_size, "octocap_take_info_t.struct_size must be " + std::to_string(sizeof(octocap_take_info_t)));
    octocap_take_info_t info{};
    info.struct_size = sizeof info;
    info.camera_count = static_cast<uint32_t>(r->reader->camera_count());
    info.frame_count = static_cast<uint32_t>(std::min<size_t>(r->reader->frame_count(), UINT32_MAX));
    info.frames_per_second = r->reader->fps();
    *out = info;
  });
}

octocap_result_t octocap_take_reader_camera_name(const octocap_take_reader_t* r, uint32_t camera, const char** name) {
  return capi::guard([&] {
    capi::checked(r, "take reader");
    capi::require(name, "name");
    const auto& names = r->reader->camera_names();
    if (camera >= names.size())
      throw Error(Errc::invalid_argument, "camera " + std::to_string(camera) + " out of range (the take has " +
                                              std::to_string(names.size()) + ")");
    *name = names[camera].c_str();
  });
}

octocap_result_t octocap_take_reader_read(octocap_take_reader_t* r, uint32_t frame, octocap_image_t* images,
                                          uint32_t capacity, uint32_t* count) {
  return capi::guard([&] {
    capi::checked(r, "take reader");
    capi::require(images, "images");
    const auto cameras = static_cast<uint32_t>(r->reader->camera_count());
    if (count) *count = cameras;
    if (capacity < cameras)
      throw Error(Errc::buffer_too_small, "capacity " + std::to_string(capacity) + " < " + std::to_string(cameras) +
                                              " cameras");
    const std::vector<cv::Mat>& pictures = r->reader->read(frame);
    for (uint32_t c = 0; c < cameras; ++c) {
      const cv::Mat& m = pictures[c];
      images[c] = {m.data, static_cast<uint32_t>(m.cols), static_cast<uint32_t>(m.rows),
                   static_cast<uint32_t>(m.step[0]), OCTOCAP_PIXELS_BGR8};
    }
  });
}

}  // extern "C"
