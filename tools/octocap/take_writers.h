// The files a take is written to, for one person (TRC, CSV, BVH as given) or several (OUT.trc -> OUT_person<ID>.trc
// and a BVH per person, each as long as the take with empty frames where the person was not there; one CSV with a
// person column). Each file is written when closed at the end: a take that fails on the way leaves none behind. A
// journaled take (live) also keeps each take's frames in FILE.partial.csv as they come, so a process killed mid-take
// leaves them; the journal goes once the files are written.
#pragma once
#include <string>
#include <vector>

#include "octocap/octocap.hpp"

// --people: "auto" (everyone, 0) or N.
uint32_t max_people_of(const std::string& people);

class TakeWriters {
 public:
  // Empty paths are not written. `rate_hz` 0: TRC and BVH at the take's own mean rate (a live take), see
  // octocap_motion_writer_create().
  TakeWriters(std::string trc, std::string csv, std::string bvh, octocap_layout_t layout, octocap_up_axis_t up,
              double rate_hz, bool several, bool journaled = false);
  void add(const octocap::Frame& frame);
  void close();
  // The files written, for the summary line.
  std::string written() const;
  // The journals being kept (journaled takes), for the start line.
  std::string journals() const;

 private:
  struct Take {
    uint32_t id;
    std::vector<octocap::MotionWriter> writers;
  };
  Take& take_of(uint32_t id);
  void journal(octocap::MotionWriter& first_of_a_take, const std::string& path);

  std::string trc_, csv_, bvh_;
  octocap_layout_t layout_;
  octocap_up_axis_t up_;
  double rate_;
  bool several_;
  bool journaled_;
  std::vector<std::string> journals_;
  std::vector<octocap::MotionWriter> shared_;  // one person: all files; several: the CSV
  std::vector<Take> takes_;                    // several: per person
  std::vector<int64_t> times_us_;              // several: each frame's time, for a person who comes later
};
