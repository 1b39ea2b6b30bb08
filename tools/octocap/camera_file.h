// Cameras from a file (--cameras cameras.toml), so that a camera's password is on neither the command line nor in `ps`:
//   [[camera]]
//   url = "rtsp://admin:S3cret@10.0.0.21/stream1"
//   name = "cam01"    # optional: a capture node's CAMERA of dds://NODE/CAMERA
// The file must be readable by its owner only (chmod 600): one that others may read is refused, naming the fix.
#pragma once
#include <string>
#include <vector>

// Appends the file's cameras (and their names, "" where none is given) in the file's order. Throws
// std::runtime_error naming the file and what is wrong; never prints a URL with its password.
void read_camera_file(const std::string& path, std::vector<std::string>& cameras, std::vector<std::string>& names);
