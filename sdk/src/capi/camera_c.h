// Camera <-> octocap_camera_t.
#pragma once
#include "core/camera.h"
#include "octocap/octocap.h"

namespace octocap::internal::capi {
void camera_to_c(const Camera& cam, octocap_camera_t& out);
}
