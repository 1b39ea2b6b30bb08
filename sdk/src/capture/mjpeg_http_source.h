// An MJPEG network camera over plain HTTP (the usual webcam-class IP camera, ffmpeg -f mpjpeg, mjpg-streamer), read
// with libcurl and decoded with libjpeg-turbo rather than through FFmpeg, because a live camera needs what FFmpeg's
// reader does not give: the reason a camera cannot be opened (refused, unknown host, 404, no answer); a corrupt
// picture skipped and counted instead of ending the connection; a part announcing gigabytes refused at once; the
// newest picture when the reader fell behind, not a queue in the connection; and an open or read that a stop ends
// within a fraction of a second. A server that answers with anything but multipart/x-mixed-replace (a video file,
// an HLS or TS stream over HTTP) is handed to FFmpeg as before.
#pragma once
#include <memory>

#include "capture/frame_source.h"

namespace octocap::internal {

std::unique_ptr<FrameSource> make_mjpeg_http_source(const CameraSpec& spec, const SourceOptions& options);

}  // namespace octocap::internal
