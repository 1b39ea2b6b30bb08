// Skeleton streaming over Cyclone DDS between two real processes on loopback: `octocap solve --publish` in a
// child process, the subscriber here, checked against a session solving the same recording in this process.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "octocap/octocap.h"
#include "octocap_stream.h"
#include "core/clock.h"
#include "stream/dds_entities.h"
#include "stream/keypoint_publisher.h"
#include "stream/remote_feed.h"
#include "support/capi_helpers.h"
#include "support/child_process.h"
#include "support/live_helpers.h"
#include "support/loopback_dds.h"

namespace {

const std::string kSample = std::string(OCTOCAP_SOURCE_DIR) + "/data/sample";
constexpr int kRate = 200;  // Hz: 90 frames in under half a second

uint32_t test_domain() { return testing::loopback_dds_domain(); }

struct SubscriberDeleter {
  void operator()(octocap_subscriber_t* s) const { octocap_subscriber_destroy(s); }
};
using Subscriber = std::unique_ptr<octocap_subscriber_t, SubscriberDeleter>;

Subscriber subscribe(const std::string& topic, octocap_stream_qos_t qos) {
  octocap_subscriber_config_t cfg;
  octocap_subscriber_config_init(&cfg);
  cfg.domain_id = test_domain();
  cfg.qos = qos;
  std::snprintf(cfg.topic, sizeof cfg.topic, "%s", topic.c_str());
  octocap_subscriber_t* s = nullptr;
  INFO(octocap_last_error());
  REQUIRE(octocap_subscriber_create(&cfg, &s) == OCTOCAP_OK);
  return Subscriber(s);
}

std::vector<std::string> publisher_args(const std::string& topic, const std::string& qos, unsigned start_frame,
                                        double linger_s, bool wait_for_subscriber = true) {
  return {OCTOCAP_CLI_PATH, "solve", "--calibration", kSample + "/calibration.toml", "--keypoints",
          kSample + "/keypoints", "--output", "/dev/null", "--quiet", "--publish", "--publish-qos", qos,
          "--domain", std::to_string(test_domain()), "--topic", topic, "--rate", std::to_string(kRate),
          "--start-frame", std::to_string(start_frame), "--linger-s", std::to_string(linger_s),
          "--wait-subscribers", wait_for_subscriber ? "1" : "0"};
}

// What the publisher computes, computed here: same recording, same config, same timestamps.
struct Reference {
  std::vector<std::vector<octocap_joint_t>> keypoints;
  std::vector<std::vector<octocap_bone_pose_t>> bones;
};

Reference solve_here() {
  octocap_calibration_t* c = nullptr;
  REQUIRE(octocap_calibration_load((kSample + "/calibration.toml").c_str(), &c) == OCTOCAP_OK);
  testing::Calib calib(c);
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open((kSample + "/keypoints").c_str(), OCTOCAP_LAYOUT_AUTO, &rec) == OCTOCAP_OK);
  octocap_layout_t layout;
  uint32_t frames = 0;
  octocap_recording_layout(rec, &layout);
  octocap_recording_frame_count(rec, &frames);
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.layout = layout;
  testing::Session s = testing::make_session(calib.get(), cfg);
  Reference ref;
  std::vector<octocap_keypoint2d_t> buf(4096);
  uint32_t people[8], n = 0;
  for (uint32_t f = 0; f < frames; ++f) {
    REQUIRE(octocap_recording_read_frame(rec, f, buf.data(), 4096, &n, people, 5) == OCTOCAP_OK);
    const int64_t t = static_cast<int64_t>(std::llround(f * 1e6 / kRate));
    REQUIRE(octocap_session_solve_keypoints(s.get(), buf.data(), people, 5, t) == OCTOCAP_OK);
    std::vector<octocap_joint_t> k(25);
    std::vector<octocap_bone_pose_t> b(OCTOCAP_BONE_COUNT);
    REQUIRE(octocap_session_get_keypoints3d(s.get(), k.data(), 25, &n) == OCTOCAP_OK);
    REQUIRE(octocap_session_get_bones(s.get(), OCTOCAP_FRAME_RIG, b.data(), OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
    ref.keypoints.push_back(k);
    ref.bones.push_back(b);
  }
  octocap_recording_destroy(rec);
  return ref;
}

// Takes one frame and checks it equals the reference, byte for byte.
// Through the frame family, and through the deprecated per-subscriber queries of the same current frame.
int64_t take_and_compare(octocap_subscriber_t* sub, const Reference& ref, int timeout_ms) {
  octocap_frame_t* frame = nullptr;
  const octocap_result_t r = octocap_subscriber_take_frame(sub, timeout_ms, &frame);
  if (r == OCTOCAP_STATUS_TIMEOUT) {
    REQUIRE(frame == nullptr);
    return -1;
  }
  REQUIRE(r == OCTOCAP_OK);
  octocap_frame_summary_t s{};
  s.struct_size = sizeof s;
  REQUIRE(octocap_frame_get_summary(frame, &s) == OCTOCAP_OK);
  REQUIRE(s.frame_index >= 0);
  REQUIRE(static_cast<size_t>(s.frame_index) < ref.keypoints.size());
  REQUIRE(s.person_count == 1);
  REQUIRE(s.source_id == 1);  // the publisher's default id
  REQUIRE(s.definition_counter != 0);
  REQUIRE(s.layout == OCTOCAP_LAYOUT_BODY_25);
  std::vector<octocap_joint_t> k(25), k_old(25);
  std::vector<octocap_bone_pose_t> b(OCTOCAP_BONE_COUNT), b_old(OCTOCAP_BONE_COUNT);
  uint32_t n = 0;
  REQUIRE(octocap_frame_get_keypoints3d(frame, 0, k.data(), 25, &n) == OCTOCAP_OK);
  REQUIRE(n == 25);
  REQUIRE(octocap_frame_get_bones(frame, 0, OCTOCAP_FRAME_RIG, b.data(), OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
  octocap_frame_release(frame);
  REQUIRE(octocap_subscriber_get_keypoints3d(sub, k_old.data(), 25, &n) == OCTOCAP_OK);
  REQUIRE(octocap_subscriber_get_bones(sub, OCTOCAP_FRAME_RIG, b_old.data(), OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
  REQUIRE(std::memcmp(k.data(), ref.keypoints[s.frame_index].data(), 25 * sizeof(octocap_joint_t)) == 0);
  REQUIRE(std::memcmp(b.data(), ref.bones[s.frame_index].data(), b.size() * sizeof(octocap_bone_pose_t)) == 0);
  REQUIRE(std::memcmp(k.data(), k_old.data(), 25 * sizeof(octocap_joint_t)) == 0);
  REQUIRE(std::memcmp(b.data(), b_old.data(), b.size() * sizeof(octocap_bone_pose_t)) == 0);
  return s.frame_index;
}

// Takes one frame; returns its frame number, -1 on timeout.
int64_t take_index(octocap_subscriber_t* sub, int timeout_ms) {
  if (octocap_subscriber_take(sub, timeout_ms) != OCTOCAP_OK) return -1;
  octocap_frame_info_t info;
  REQUIRE(octocap_subscriber_get_frame_info(sub, &info) == OCTOCAP_OK);
  return info.frame_index;
}

// A writer that does not go through octocap (record profile), for samples octocap would never write.
struct RawWriter {
  octocap::internal::DdsParticipant participant{test_domain()};
  dds_entity_t writer = 0;
  RawWriter(const dds_topic_descriptor_t* type, const std::string& topic) {
    octocap::internal::StreamConfig sc;
    sc.qos = octocap::internal::StreamQos::record;
    const dds_entity_t t = participant.topic(type, topic);
    dds_qos_t* q = octocap::internal::pose_qos(sc);
    writer = dds_create_writer(participant.get(), t, q, nullptr);
    dds_delete_qos(q);
    REQUIRE(writer > 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // discovery
  }
  template <class Sample>
  void write(const Sample& sample) {
    REQUIRE(dds_write(writer, &sample) == DDS_RETCODE_OK);
  }
};

// Counts the library's "... rejected ..." warnings while it lives.
struct RejectionLog {
  static inline int warnings = 0;
  RejectionLog() {
    warnings = 0;
    octocap_set_log_callback([](octocap_log_level_t l, const char* m, void*) {
      if (l == OCTOCAP_LOG_WARNING && std::strstr(m, "rejected")) ++warnings;
    }, OCTOCAP_LOG_DEBUG, nullptr);
  }
  ~RejectionLog() { octocap_set_log_callback(nullptr, OCTOCAP_LOG_DEBUG, nullptr); }
};

}  // namespace

TEST_CASE("every frame arrives in another process bit-identical (record profile)", "[stream]") {
  const Reference ref = solve_here();
  Subscriber sub = subscribe("all_frames", OCTOCAP_QOS_RECORD);
  testing::ChildProcess publisher(publisher_args("all_frames", "record", 0, 1.0));
  REQUIRE(publisher.started());
  int64_t expected = 0;
  while (expected < 90) {
    const int64_t f = take_and_compare(sub.get(), ref, 10000);
    REQUIRE(f == expected);  // in order, none lost
    ++expected;
  }
  REQUIRE(publisher.wait() == 0);
  octocap_stream_info_t info;
  REQUIRE(octocap_subscriber_get_stream_info(sub.get(), &info) == OCTOCAP_OK);
  REQUIRE(info.frames_received == 90);
  REQUIRE(info.frames_lost == 0);
  REQUIRE(info.has_definition == 1);
  REQUIRE(info.layout == OCTOCAP_LAYOUT_BODY_25);
}

TEST_CASE("a late joiner gets the latest pose with the record profile", "[stream]") {
  const Reference ref = solve_here();
  testing::ChildProcess publisher(publisher_args("late_joiner", "record", 0, 4.0, false));
  REQUIRE(publisher.started());
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // all 90 frames are out before we join
  Subscriber sub = subscribe("late_joiner", OCTOCAP_QOS_RECORD);
  int64_t last = -1;
  for (int64_t f; (f = take_and_compare(sub.get(), ref, 2000)) >= 0;) last = f;
  REQUIRE(last == 89);
  octocap_stream_info_t info;
  REQUIRE(octocap_subscriber_get_stream_info(sub.get(), &info) == OCTOCAP_OK);
  REQUIRE(info.has_definition == 1);  // the definition reached the late joiner too
}

TEST_CASE("a publisher killed mid-stream and restarted is picked up again, the gap reported", "[stream]") {
  // B and C start from other frames than A, so their filters start afresh: frame numbers and counters are
  // what is checked here (bit-identity is the first test's job).
  Subscriber sub = subscribe("restart", OCTOCAP_QOS_RECORD);
  int64_t last_a = -1;
  {
    std::vector<std::string> args = publisher_args("restart", "record", 0, 0);
    args[args.size() - 7] = "30";  // --rate 30: slow enough to be killed mid-stream
    testing::ChildProcess a(args);
    while (last_a < 10) {
      last_a = take_index(sub.get(), 10000);
      REQUIRE(last_a >= 0);
    }
    a.kill_now();
    a.wait();
  }
  for (int64_t f; (f = take_index(sub.get(), 300)) >= 0;) last_a = f;  // frames still in flight from A
  REQUIRE(last_a < 60);
  testing::ChildProcess b(publisher_args("restart", "record", 60, 1.0));
  REQUIRE(take_index(sub.get(), 10000) == 60);
  octocap_stream_info_t info;
  REQUIRE(octocap_subscriber_get_stream_info(sub.get(), &info) == OCTOCAP_OK);
  REQUIRE(info.last_gap == static_cast<uint64_t>(60 - last_a - 1));
  REQUIRE(info.frames_lost == info.last_gap);
  REQUIRE(info.restarts == 0);
  int64_t f = 60, expected = 61;
  while (f < 89) {
    f = take_index(sub.get(), 10000);
    REQUIRE(f == expected++);
  }
  b.wait();
  // A third run from frame 0: the numbers go backwards, which is a restart, not a gap.
  testing::ChildProcess c(publisher_args("restart", "record", 0, 1.0));
  REQUIRE(take_index(sub.get(), 10000) == 0);
  REQUIRE(octocap_subscriber_get_stream_info(sub.get(), &info) == OCTOCAP_OK);
  REQUIRE(info.restarts == 1);
  REQUIRE(info.last_gap == 0);
  c.wait();
}

TEST_CASE("samples of another wire version are rejected with a log message", "[stream]") {
  const RejectionLog log;
  Subscriber sub = subscribe("bad_samples", OCTOCAP_QOS_RECORD);
  {
    // A future version and a malformed pose.
    RawWriter w(&octocap_wire_Pose_desc, "bad_samples_pose");
    octocap_wire_Pose pose{};
    pose.version = 99;
    w.write(pose);
    pose.version = octocap_wire_VERSION;  // right version, but no keypoints / joints / bones
    pose.frame_number = 1;
    w.write(pose);
    REQUIRE(octocap_subscriber_take(sub.get(), 1500) == OCTOCAP_ERROR_NO_RESULT);  // 0.x: an error code
    octocap_frame_t* frame = reinterpret_cast<octocap_frame_t*>(0x1);
    REQUIRE(octocap_subscriber_take_frame(sub.get(), 100, &frame) == OCTOCAP_STATUS_TIMEOUT);  // 1.0: a status
    REQUIRE(frame == nullptr);
  }
  octocap_stream_info_t info;
  REQUIRE(octocap_subscriber_get_stream_info(sub.get(), &info) == OCTOCAP_OK);
  REQUIRE(info.rejected == 2);
  REQUIRE(info.frames_received == 0);
  REQUIRE(RejectionLog::warnings == 2);
  octocap_joint_t j[25];
  uint32_t n = 0;
  REQUIRE(octocap_subscriber_get_keypoints3d(sub.get(), j, 25, &n) == OCTOCAP_ERROR_NO_RESULT);
}

TEST_CASE("malformed several-people samples are rejected with a log message, never a crash", "[stream][people]") {
  const RejectionLog log;
  Subscriber sub = subscribe("bad_people", OCTOCAP_QOS_RECORD);
  {
    RawWriter w(&octocap_wire_PeopleFrame_desc, "bad_people_people");
    // Two people with the same id, then a person whose sequences do not match the skeleton, then a NaN error.
    octocap_wire_PersonPose people[2]{};
    people[0].person_id = people[1].person_id = 3;
    octocap_wire_PeopleFrame frame{};
    frame.version = octocap_wire_VERSION;
    frame.frame_number = 1;
    frame.people._buffer = people;
    frame.people._length = frame.people._maximum = 2;
    w.write(frame);
    people[1].person_id = 4;  // ids fine now, but no keypoints, joints or bones
    frame.frame_number = 2;
    w.write(frame);
    frame.people._length = 0;
    frame.mean_reprojection_error_px = NAN;
    frame.frame_number = 3;
    w.write(frame);
    octocap_frame_t* out = nullptr;
    REQUIRE(octocap_subscriber_take_frame(sub.get(), 1500, &out) == OCTOCAP_STATUS_TIMEOUT);
    REQUIRE(out == nullptr);
    // An empty frame (nobody this frame) is a frame, with no people.
    frame.mean_reprojection_error_px = 0;
    frame.frame_number = 4;
    w.write(frame);
    REQUIRE(octocap_subscriber_take_frame(sub.get(), 5000, &out) == OCTOCAP_OK);
    octocap_frame_summary_t summary{};
    summary.struct_size = sizeof summary;
    REQUIRE(octocap_frame_get_summary(out, &summary) == OCTOCAP_OK);
    CHECK(summary.frame_index == 4);
    CHECK(summary.person_count == 0);
    octocap_frame_release(out);
  }
  octocap_stream_info_t info;
  REQUIRE(octocap_subscriber_get_stream_info(sub.get(), &info) == OCTOCAP_OK);
  CHECK(info.rejected == 3);
  CHECK(info.frames_received == 1);
  CHECK(RejectionLog::warnings == 3);
}

TEST_CASE("a publishing session survives subscriber churn and never blocks", "[stream]") {
  octocap_calibration_t* c = nullptr;
  REQUIRE(octocap_calibration_load((kSample + "/calibration.toml").c_str(), &c) == OCTOCAP_OK);
  testing::Calib calib(c);
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open((kSample + "/keypoints").c_str(), OCTOCAP_LAYOUT_AUTO, &rec) == OCTOCAP_OK);
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.stream_enable = 1;
  cfg.stream_domain_id = test_domain();
  std::snprintf(cfg.stream_topic, sizeof cfg.stream_topic, "churn");
  testing::Session s = testing::make_session(calib.get(), cfg);
  std::vector<octocap_keypoint2d_t> buf(4096);
  uint32_t people[8], n = 0;
  Subscriber sub;
  uint64_t received = 0;
  for (uint32_t f = 0; f < 90; ++f) {
    if (f % 15 == 0) sub = subscribe("churn", OCTOCAP_QOS_LIVE);  // a new subscriber, the old one leaves
    REQUIRE(octocap_recording_read_frame(rec, f, buf.data(), 4096, &n, people, 5) == OCTOCAP_OK);
    REQUIRE(octocap_session_solve_keypoints(s.get(), buf.data(), people, 5, f * 33333) == OCTOCAP_OK);
    REQUIRE(octocap_session_flush_stream(s.get()) == OCTOCAP_OK);
    if (octocap_subscriber_take(sub.get(), 200) == OCTOCAP_OK) ++received;
  }
  octocap_recording_destroy(rec);
  // Best effort and fresh subscribers miss a few frames while discovery runs; most arrive.
  CHECK(received > 45);
}

TEST_CASE("stream configuration errors", "[stream]") {
  octocap_subscriber_config_t cfg;
  octocap_subscriber_config_init(&cfg);
  octocap_subscriber_t* s = nullptr;
  cfg.qos = 7;
  REQUIRE(octocap_subscriber_create(&cfg, &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_subscriber_config_init(&cfg);
  std::snprintf(cfg.topic, sizeof cfg.topic, "no/slashes");
  REQUIRE(octocap_subscriber_create(&cfg, &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  REQUIRE_THAT(octocap_last_error(), Catch::Matchers::ContainsSubstring("topic"));
  octocap_subscriber_config_init(&cfg);
  cfg.struct_size = 4;
  REQUIRE(octocap_subscriber_create(&cfg, &s) == OCTOCAP_ERROR_STRUCT_SIZE);
  REQUIRE(octocap_subscriber_take(nullptr, 0) == OCTOCAP_ERROR_INVALID_HANDLE);
  REQUIRE(s == nullptr);
}

TEST_CASE("a publisher that comes back with another skeleton changes the received definition counter", "[stream]") {
  const std::string demo = std::string(OCTOCAP_REAL_DATA_DIR) + "/Demo";
  Subscriber sub = subscribe("relayout", OCTOCAP_QOS_RECORD);
  auto take_summary = [&](octocap_frame_summary_t& s) {
    octocap_frame_t* frame = nullptr;
    REQUIRE(octocap_subscriber_take_frame(sub.get(), 10000, &frame) == OCTOCAP_OK);
    s = octocap_frame_summary_t{};
    s.struct_size = sizeof s;
    REQUIRE(octocap_frame_get_summary(frame, &s) == OCTOCAP_OK);
    octocap_frame_release(frame);
  };
  octocap_frame_summary_t first{}, later{}, other{};
  {
    std::vector<std::string> args = publisher_args("relayout", "record", 0, 0.5);
    args.insert(args.end(), {"--frames", "5"});
    testing::ChildProcess a(args);  // the sample: BODY_25
    take_summary(first);
    for (int i = 1; i < 5; ++i) take_summary(later);
    REQUIRE(a.wait() == 0);
  }
  CHECK(first.layout == OCTOCAP_LAYOUT_BODY_25);
  CHECK(later.definition_counter == first.definition_counter);  // same publisher, same skeleton
  // Pose2Sim's real demo: BODY_25B, same topic and source id.
  std::vector<std::string> args = publisher_args("relayout", "record", 0, 0.5);
  args[3] = demo + "/calibration/Calib_qualisys.toml";
  args[5] = demo + "/pose";
  args.insert(args.end(), {"--frames", "5"});
  testing::ChildProcess b(args);
  for (int i = 0; i < 5; ++i) take_summary(other);  // the last: its definition has certainly arrived by then
  REQUIRE(b.wait() == 0);
  CHECK(other.layout == OCTOCAP_LAYOUT_BODY_25B);
  CHECK(other.definition_counter != first.definition_counter);  // consumers re-read the definition
  CHECK(other.definition_counter != 0);
}

TEST_CASE("remote cameras: two capture nodes under one name are not merged; the one heard first is kept",
          "[stream][nodes]") {
  const uint32_t domain = testing::loopback_dds_domain();
  const std::string topic = "octocap_dup_" + std::to_string(getpid());
  auto receiver = std::make_shared<octocap::internal::KeypointReceiver>(domain, topic);
  octocap::internal::FeedOptions options;
  options.source.open_timeout_ms = 10000;
  octocap::internal::RemoteFeed feed(octocap::internal::parse_camera_spec("dds://nodeA/cam01"), options, receiver, [] {});
  octocap::internal::KeypointPublisher first(domain, topic), second(domain, topic);
  REQUIRE(testing::wait_until([&] { return first.matched_readers() >= 1 && second.matched_readers() >= 1; }, 10000));
  auto view = [](uint64_t frame) {
    octocap::internal::RemoteView v;
    v.node = "nodeA";
    v.camera = "cam01";
    v.frame_number = frame;
    v.capture_time_us = octocap::internal::wall_clock_us();
    v.nominal_fps = 50;
    v.width = 640;
    v.height = 480;
    return v;
  };
  // Two nodes at 50 Hz, half a period apart, as two processes would be: the first alone for 1 s, then both for 2 s
  // (the second's frame numbers start at 1, as a node's do), then the second alone for 2 s, once the first is gone.
  std::atomic<bool> both_done{false};
  const auto t0 = std::chrono::steady_clock::now();
  auto node = [&](octocap::internal::KeypointPublisher& p, int first_tick, int last_tick, int phase_ms) {
    for (int tick = first_tick; tick <= last_tick; ++tick) {
      std::this_thread::sleep_until(t0 + std::chrono::milliseconds(20 * tick + phase_ms));
      p.publish(view(static_cast<uint64_t>(tick - first_tick + 1)));
    }
  };
  std::thread node_a([&] {
    node(first, 0, 150, 0);
    both_done = true;
  });
  std::thread node_b([&] { node(second, 50, 250, 10); });
  feed.start();
  REQUIRE(testing::wait_until([&] { return both_done.load(); }, 20000));
  const octocap::internal::FeedStatus during = feed.status();
  node_a.join();
  node_b.join();
  const octocap::internal::FeedStatus after = feed.status();
  feed.stop();
  INFO("during: " << during.grabbed << " grabbed, " << during.reconnects << " reconnects; after: " << after.grabbed);
  CHECK(during.reconnects == 0);   // merged, the interleaved frame numbers looked like a restart each time
  CHECK(during.grabbed <= 151);    // the first node published 151; merged, the camera's rate doubled
  CHECK_THAT(during.last_error, Catch::Matchers::ContainsSubstring("two capture nodes publish as 'nodeA'"));
  CHECK(after.grabbed > during.grabbed + 20);  // the second takes over once the first fell silent
}
