#include "take_writers.h"

#include <algorithm>
#include <filesystem>

namespace {

std::string person_path(const std::string& path, uint32_t id) {
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "_person" + std::to_string(id) + p.extension().string())).string();
}

}  // namespace

uint32_t max_people_of(const std::string& people) {
  return people == "auto" ? 0u : static_cast<uint32_t>(std::stoul(people));
}

TakeWriters::TakeWriters(std::string trc, std::string csv, std::string bvh, octocap_layout_t layout,
                         octocap_up_axis_t up, double rate_hz, bool several, bool journaled)
    : trc_(std::move(trc)), csv_(std::move(csv)), bvh_(std::move(bvh)), layout_(layout), up_(up), rate_(rate_hz),
      several_(several), journaled_(journaled) {
  if (several_) {
    if (!csv_.empty()) shared_.emplace_back(csv_, OCTOCAP_MOTION_CSV_PEOPLE, layout_, up_, rate_);
    if (!shared_.empty()) journal(shared_.front(), csv_);
    return;
  }
  if (!trc_.empty()) shared_.emplace_back(trc_, OCTOCAP_MOTION_TRC, layout_, up_, rate_);
  if (!csv_.empty()) shared_.emplace_back(csv_, OCTOCAP_MOTION_CSV, layout_, up_, rate_);
  if (!bvh_.empty()) shared_.emplace_back(bvh_, OCTOCAP_MOTION_BVH, layout_, up_, rate_);
  // One journal holds the take's keypoints, whatever files it will be: the first file's.
  if (!shared_.empty()) journal(shared_.front(), !trc_.empty() ? trc_ : !csv_.empty() ? csv_ : bvh_);
}

void TakeWriters::journal(octocap::MotionWriter& first_of_a_take, const std::string& path) {
  if (!journaled_) return;
  journals_.push_back(path + ".partial.csv");
  first_of_a_take.set_journal(journals_.back());
}

std::string TakeWriters::journals() const {
  std::string s;
  for (const std::string& j : journals_) s += (s.empty() ? "" : ", ") + j;
  return s;
}

TakeWriters::Take& TakeWriters::take_of(uint32_t id) {
  for (Take& t : takes_)
    if (t.id == id) return t;
  Take t{id, {}};
  if (!trc_.empty()) t.writers.emplace_back(person_path(trc_, id), OCTOCAP_MOTION_TRC, layout_, up_, rate_);
  if (!bvh_.empty()) t.writers.emplace_back(person_path(bvh_, id), OCTOCAP_MOTION_BVH, layout_, up_, rate_);
  // Several people without a CSV: each person's take has a journal of its own (with a CSV, that one holds them all).
  if (csv_.empty() && !t.writers.empty()) journal(t.writers.front(), person_path(!trc_.empty() ? trc_ : bvh_, id));
  for (int64_t time_us : times_us_)
    for (octocap::MotionWriter& w : t.writers) w.add_empty(time_us);
  takes_.push_back(std::move(t));
  return takes_.back();
}

void TakeWriters::add(const octocap::Frame& frame) {
  if (!several_) {
    for (octocap::MotionWriter& w : shared_) w.add(frame, 0);
    return;
  }
  const octocap_frame_summary_t summary = frame.summary();
  const uint32_t present = summary.person_count;
  std::vector<uint32_t> seen;
  for (uint32_t i = 0; i < present; ++i) {
    for (octocap::MotionWriter& w : shared_) w.add(frame, i);
    const uint32_t id = frame.person(i).id;
    for (octocap::MotionWriter& w : take_of(id).writers) w.add(frame, i);
    seen.push_back(id);
  }
  for (Take& t : takes_)
    if (std::find(seen.begin(), seen.end(), t.id) == seen.end())
      for (octocap::MotionWriter& w : t.writers) w.add_empty(summary.timestamp_us);
  times_us_.push_back(summary.timestamp_us);
}

void TakeWriters::close() {
  for (octocap::MotionWriter& w : shared_) w.close();
  for (Take& t : takes_)
    for (octocap::MotionWriter& w : t.writers) w.close();
}

std::string TakeWriters::written() const {
  std::string s;
  auto add = [&](const std::string& path) {
    if (!path.empty()) s += (s.empty() ? "" : ", ") + path;
  };
  if (!several_) {
    add(trc_), add(csv_), add(bvh_);
  } else {
    for (const Take& t : takes_) {
      if (!trc_.empty()) add(person_path(trc_, t.id));
      if (!bvh_.empty()) add(person_path(bvh_, t.id));
    }
    add(csv_);
  }
  return s.empty() ? "no file" : s;
}
