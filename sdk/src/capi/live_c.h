// What the live-capture and capture-node handles share at the C boundary.
#pragma once
#include <string>

#include "capture/feed_status.h"
#include "octocap/octocap.h"

namespace octocap::capi {

// A camera's status into the caller's struct (its struct_size bytes).
void fill_camera_status(const FeedStatus& s, const std::string& name, octocap_camera_status_t* out);

}  // namespace octocap::capi
