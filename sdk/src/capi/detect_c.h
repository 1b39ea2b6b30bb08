// The detector's C structs <-> the core's DetectorConfig (shared by the detector and session entry points).
#pragma once
#include "detect/detector.h"
#include "octocap/octocap.h"

namespace octocap::internal::capi {

DetectorConfig detector_config(const octocap_detector_config_t& c);
octocap_detector_config_t c_detector_config(const DetectorConfig& d);
std::vector<ImageView> image_views(const octocap_image_t* images, uint32_t count);
void fill_detect_info(const Detector& detector, octocap_detect_info_t* out);

}  // namespace octocap::internal::capi
