// Secrets out of text: a camera URL's password (rtsp://admin:S3cret@host/x -> rtsp://admin:***@host/x) must never
// reach a message, a log line, a status or an error string, where users paste it into bug reports. One home: the log
// sink, the C ABI's last error and its camera statuses all pass through here.
#pragma once
#include <string>

namespace octocap::internal {

// `text` with the password of every URL in it (scheme://user:password@host...) replaced by ***; the user name and
// the rest stay, so that the message still says which camera.
std::string redact_credentials(const std::string& text);

}  // namespace octocap::internal
