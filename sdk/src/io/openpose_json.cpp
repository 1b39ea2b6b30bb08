#include "io/openpose_json.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/log.h"
#include "io/directories.h"

namespace fs = std::filesystem;

namespace octocap::internal {
namespace {

// BODY_25 and BODY_25B both have 25 keypoints. In BODY_25, keypoint 1 (neck) sits midway between 2 and 5
// (the shoulders); in BODY_25B keypoint 1 is the left eye, 2 the right eye and 5 the left shoulder, so it is
// nowhere near their midpoint. The median over the people seen decides.
LayoutId disambiguate_25(const std::vector<Person2D>& people) {
  std::vector<double> ratios;
  for (const auto& p : people) {
    const auto& a = p[1];
    const auto& b = p[2];
    const auto& c = p[5];
    if (a.confidence <= 0 || b.confidence <= 0 || c.confidence <= 0) continue;
    const double span = std::hypot(b.x - c.x, b.y - c.y);
    if (span < 1e-6) continue;
    ratios.push_back(std::hypot(a.x - 0.5 * (b.x + c.x), a.y - 0.5 * (b.y + c.y)) / span);
  }
  if (ratios.empty()) return LayoutId::body25;
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  return ratios[ratios.size() / 2] < 0.3 ? LayoutId::body25 : LayoutId::body25b;
}

}  // namespace

std::vector<Person2D> read_openpose_file(const std::string& path, size_t keypoint_count) {
  std::ifstream in(path);
  if (!in) throw Error(Errc::io, path + ": cannot open keypoint file");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for numbers like 1e999
    throw Error(Errc::parse, path + ": malformed JSON: " + e.what());
  }
  if (!doc.is_object() || !doc.contains("people") || !doc["people"].is_array())
    throw Error(Errc::parse, path + ": not OpenPose JSON (no 'people' array)");
  std::vector<Person2D> people;
  size_t index = 0;
  for (const auto& p : doc["people"]) {
    const std::string where = path + ": people[" + std::to_string(index++) + "]";
    if (!p.is_object() || !p.contains("pose_keypoints_2d") || !p["pose_keypoints_2d"].is_array())
      throw Error(Errc::parse, where + ": no 'pose_keypoints_2d' array");
    const auto& arr = p["pose_keypoints_2d"];
    if (arr.empty()) continue;  // OpenPose writes empty arrays for people it dropped
    if (arr.size() % 3 != 0)
      throw Error(Errc::parse, where + ": 'pose_keypoints_2d' has " + std::to_string(arr.size()) +
                                   " numbers, not a multiple of 3 (x, y, confidence)");
    const size_t n = arr.size() / 3;
    const size_t expected = keypoint_count ? keypoint_count : (people.empty() ? n : people.front().size());
    if (n != expected)
      throw Error(Errc::parse, where + ": has " + std::to_string(n) + " keypoints, the layout has " +
                                   std::to_string(expected));
    Person2D person(n);
    for (size_t k = 0; k < n; ++k) {
      double v[3];
      for (int c = 0; c < 3; ++c) {
        const auto& e = arr[3 * k + c];
        if (!e.is_number()) throw Error(Errc::parse, where + ": keypoint " + std::to_string(k) + " is not numeric");
        v[c] = e.get<double>();
      }
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) v[2] = 0;
      // OpenPose marks an undetected keypoint as (0, 0, 0).
      if (v[0] == 0 && v[1] == 0) v[2] = 0;
      person[k] = {v[0], v[1], v[2]};
    }
    people.push_back(std::move(person));
  }
  return people;
}

OpenPoseRecording::OpenPoseRecording(const std::string& directory, LayoutId layout_id) : layout_(layout_id) {
  std::error_code ec;
  const std::vector<fs::path> dirs = sorted_subdirectories(directory);
  for (const auto& d : dirs) {
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(d, ec))
      if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path().string());
    if (files.empty()) continue;  // not a camera folder
    std::sort(files.begin(), files.end());
    views_.push_back(std::move(files));
    view_names_.push_back(d.filename().string());
  }
  if (views_.empty())
    throw Error(Errc::io, directory + ": no camera sub-folder holding OpenPose .json files");
  frame_count_ = views_.front().size();
  size_t longest = 0;
  for (const auto& v : views_) {
    frame_count_ = std::min(frame_count_, v.size());
    longest = std::max(longest, v.size());
  }
  if (longest != frame_count_)
    log(LogLevel::warning, directory + ": camera folders hold " + std::to_string(frame_count_) + " to " +
                               std::to_string(longest) + " files; using the first " + std::to_string(frame_count_) +
                               " frames of each");
  if (layout_ == LayoutId::automatic) {
    std::vector<Person2D> seen;
    for (size_t f = 0; f < frame_count_ && seen.size() < 20; ++f) {
      for (const auto& v : views_) {
        auto people = read_openpose_file(v[f], seen.empty() ? 0 : seen.front().size());
        for (auto& p : people) seen.push_back(std::move(p));
      }
    }
    if (seen.empty())
      throw Error(Errc::parse, directory + ": no person in any file, cannot detect the keypoint layout");
    layout_ = layout_for_count(seen.front().size());
    if (layout_ == LayoutId::body25) layout_ = disambiguate_25(seen);
  }
}

std::vector<std::vector<Person2D>> OpenPoseRecording::read_raw(size_t frame) const {
  if (frame >= frame_count_)
    throw Error(Errc::invalid_argument, "frame " + std::to_string(frame) + " out of range (recording has " +
                                            std::to_string(frame_count_) + ")");
  const size_t n = octocap::internal::layout(layout_).keypoints.size();
  std::vector<std::vector<Person2D>> out;
  for (const auto& v : views_) out.push_back(read_openpose_file(v[frame], n));
  return out;
}

void OpenPoseRecording::set_time_offsets(std::vector<double> offsets) {
  if (!offsets.empty() && offsets.size() != views_.size())
    throw Error(Errc::invalid_argument, std::to_string(offsets.size()) + " time offsets for " +
                                            std::to_string(views_.size()) + " views");
  for (double o : offsets)
    if (!std::isfinite(o) || std::abs(o) > 1e6) throw Error(Errc::invalid_argument, "a time offset is not finite");
  // An offset as long as the take leaves that view out of every frame (or most): the others are solved without it,
  // which is rarely what was meant (a sync file of another take, or seconds written as frames).
  const double frames = static_cast<double>(frame_count_);
  for (size_t v = 0; v < offsets.size(); ++v) {
    const double overlap = std::max(0.0, frames - std::abs(offsets[v]));
    if (frames > 0 && overlap < 0.5 * frames) {
      char text[256];
      std::snprintf(text, sizeof text,
                    "view %s: a time offset of %.1f frames leaves it in %.0f of the take's %.0f frames; the others "
                    "are solved without it", view_names_[v].c_str(), offsets[v], overlap, frames);
      log(LogLevel::warning, text);
    }
  }
  offsets_ = std::move(offsets);
}

std::vector<std::vector<Person2D>> OpenPoseRecording::read_frame(size_t frame) const {
  if (offsets_.empty()) return read_raw(frame);
  if (frame >= frame_count_)
    throw Error(Errc::invalid_argument, "frame " + std::to_string(frame) + " out of range (recording has " +
                                            std::to_string(frame_count_) + ")");
  const size_t n = octocap::internal::layout(layout_).keypoints.size();
  std::vector<std::vector<Person2D>> out(views_.size());
  for (size_t v = 0; v < views_.size(); ++v) {
    // This view's own frame for the first camera's frame `frame`; outside its take it saw nobody.
    const double own = static_cast<double>(frame) - offsets_[v];
    if (own < 0 || own > static_cast<double>(frame_count_ - 1)) continue;
    const size_t f0 = static_cast<size_t>(std::floor(own));
    const size_t f1 = std::min(f0 + 1, frame_count_ - 1);
    const double w = own - static_cast<double>(f0);
    const auto a = read_openpose_file(views_[v][f0], n);
    if (w < 1e-9 || f1 == f0) {
      out[v] = a;
      continue;
    }
    const auto b = read_openpose_file(views_[v][f1], n);
    // People are paired by their order when both frames hold as many; otherwise the nearer frame is taken whole.
    if (a.size() != b.size()) {
      out[v] = w < 0.5 ? a : b;
      continue;
    }
    for (size_t p = 0; p < a.size(); ++p) out[v].push_back(interpolate_person(a[p], b[p], w, 0.05));
  }
  return out;
}

}  // namespace octocap::internal

namespace octocap::internal {

void write_openpose_file(const std::string& path, const std::vector<Person2D>& people) {
  std::string text = "{\"version\":1.3,\"people\":[";
  char number[80];
  for (size_t p = 0; p < people.size(); ++p) {
    text += p ? ",{\"person_id\":[-1],\"pose_keypoints_2d\":[" : "{\"person_id\":[-1],\"pose_keypoints_2d\":[";
    for (size_t k = 0; k < people[p].size(); ++k) {
      Keypoint2D kp = people[p][k];
      // JSON has no NaN: a keypoint that is not a number is one not detected, as the reader takes it.
      if (!std::isfinite(kp.x) || !std::isfinite(kp.y) || !std::isfinite(kp.confidence)) kp = Keypoint2D{};
      std::snprintf(number, sizeof number, "%s%.10g,%.10g,%.10g", k ? "," : "", kp.x, kp.y, kp.confidence);
      text += number;
    }
    text += "]}";
  }
  text += "]}\n";
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw Error(Errc::io, path + ": cannot write keypoint file");
}

}  // namespace octocap::internal
