// VMC protocol output checked by a real OSC receiver written here: a UDP socket on loopback and a parser of
// OSC bundles written from the OSC 1.0 spec, independent of the sender's library.
#include <arpa/inet.h>
#include <catch2/catch_test_macros.hpp>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "crowd.h"
#include "io/calibration_toml.h"
#include "octocap/octocap.h"
#include "support/capi_helpers.h"
#include "support/temp_dir.h"

namespace {

struct OscMessage {
  std::string address;
  std::string name;  // first string argument, if any
  std::vector<float> floats;
  std::vector<int32_t> ints;
};

struct Reader {
  const uint8_t* p;
  size_t left;
  uint32_t u32() {
    REQUIRE(left >= 4);
    uint32_t v;
    std::memcpy(&v, p, 4);
    p += 4;
    left -= 4;
    return ntohl(v);
  }
  std::string str() {
    const size_t n = strnlen(reinterpret_cast<const char*>(p), left);
    REQUIRE(n < left);
    std::string s(reinterpret_cast<const char*>(p), n);
    const size_t padded = (n + 4) & ~size_t{3};
    p += padded;
    left -= padded;
    return s;
  }
};

OscMessage parse_message(const uint8_t* data, size_t size) {
  Reader r{data, size};
  OscMessage m;
  m.address = r.str();
  const std::string tags = r.str();
  REQUIRE(tags[0] == ',');
  for (char t : tags.substr(1)) {
    if (t == 'f') {
      const uint32_t bits = r.u32();
      float f;
      std::memcpy(&f, &bits, 4);
      m.floats.push_back(f);
    } else if (t == 'i') {
      m.ints.push_back(static_cast<int32_t>(r.u32()));
    } else if (t == 's') {
      m.name = r.str();
    } else {
      FAIL("unexpected OSC type tag " << t);
    }
  }
  return m;
}

std::vector<OscMessage> parse_bundle(const std::vector<uint8_t>& packet) {
  REQUIRE(packet.size() >= 16);
  REQUIRE(std::memcmp(packet.data(), "#bundle\0", 8) == 0);
  Reader r{packet.data() + 16, packet.size() - 16};
  std::vector<OscMessage> out;
  while (r.left > 0) {
    const uint32_t n = r.u32();
    REQUIRE(n <= r.left);
    out.push_back(parse_message(r.p, n));
    r.p += n;
    r.left -= n;
  }
  return out;
}

// A UDP socket on loopback at `port` (0: any free one); -1 when the port is taken.
int bind_udp(uint16_t port, uint16_t& bound) {
  const int sock = socket(AF_INET, SOCK_DGRAM, 0);
  REQUIRE(sock >= 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(port);
  if (bind(sock, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    close(sock);
    return -1;
  }
  socklen_t len = sizeof addr;
  REQUIRE(getsockname(sock, reinterpret_cast<sockaddr*>(&addr), &len) == 0);
  bound = ntohs(addr.sin_port);
  return sock;
}

// The next bundle waiting on `sock` (the session sends while it solves, so it is there when the solve returns); empty
// when there is none.
std::vector<OscMessage> next_bundle(int sock) {
  std::vector<uint8_t> packet(65536);
  const ssize_t got = recv(sock, packet.data(), packet.size(), MSG_DONTWAIT);
  if (got <= 0) return {};
  packet.resize(static_cast<size_t>(got));
  return parse_bundle(packet);
}

Eigen::Quaterniond quaternion(const OscMessage& m) {
  REQUIRE(m.floats.size() == 7);
  return Eigen::Quaterniond(m.floats[6], m.floats[3], m.floats[4], m.floats[5]);
}

Eigen::Vector3d position(const OscMessage& m) {
  REQUIRE(m.floats.size() == 7);
  return Eigen::Vector3d(m.floats[0], m.floats[1], m.floats[2]);
}

// What a VMC receiver does with a bundle: Unity's humanoid hierarchy from /VMC/Ext/Root/Pos down, each bone at its
// local position and rotation in its parent; the world position of every bone received.
std::map<std::string, Eigen::Vector3d> rebuild_pose(const std::vector<OscMessage>& bundle) {
  static const std::map<std::string, std::string> parent = {
      {"Spine", "Hips"}, {"Chest", "Spine"}, {"UpperChest", "Chest"}, {"Neck", "UpperChest"}, {"Head", "Neck"},
      {"RightShoulder", "UpperChest"}, {"RightUpperArm", "RightShoulder"}, {"RightLowerArm", "RightUpperArm"},
      {"RightHand", "RightLowerArm"}, {"LeftShoulder", "UpperChest"}, {"LeftUpperArm", "LeftShoulder"},
      {"LeftLowerArm", "LeftUpperArm"}, {"LeftHand", "LeftLowerArm"}, {"RightUpperLeg", "Hips"},
      {"RightLowerLeg", "RightUpperLeg"}, {"RightFoot", "RightLowerLeg"}, {"LeftUpperLeg", "Hips"},
      {"LeftLowerLeg", "LeftUpperLeg"}, {"LeftFoot", "LeftLowerLeg"}};
  std::map<std::string, const OscMessage*> local;
  const OscMessage* root = nullptr;
  for (const OscMessage& m : bundle) {
    if (m.address == "/VMC/Ext/Bone/Pos") local[m.name] = &m;
    if (m.address == "/VMC/Ext/Root/Pos") root = &m;
  }
  REQUIRE(root);
  REQUIRE(local.count("Hips"));
  struct Pose { Eigen::Vector3d p; Eigen::Quaterniond q; };
  std::map<std::string, Pose> world;
  world["Hips"] = {position(*root) + quaternion(*root) * position(*local["Hips"]),
                   quaternion(*root) * quaternion(*local["Hips"])};
  // Parents before children: a bone is placed once its parent is.
  for (bool placed = true; placed;) {
    placed = false;
    for (const auto& [name, m] : local) {
      if (world.count(name) || !parent.count(name) || !world.count(parent.at(name))) continue;
      const Pose& up = world.at(parent.at(name));
      world[name] = {up.p + up.q * position(*m), up.q * quaternion(*m)};
      placed = true;
    }
  }
  std::map<std::string, Eigen::Vector3d> out;
  for (const auto& [name, w] : world) out[name] = w.p;
  return out;
}

}  // namespace

TEST_CASE("VMC output rebuilds the solved skeleton in a receiver: every joint where octocap solved it", "[vmc]") {
  uint16_t port = 0;
  const int sock = bind_udp(0, port);
  REQUIRE(sock >= 0);
  timeval tv{2, 0};
  setsockopt(sock, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  const std::string sample = std::string(OCTOCAP_SOURCE_DIR) + "/data/sample";
  octocap_calibration_t* c = nullptr;
  REQUIRE(octocap_calibration_load((sample + "/calibration.toml").c_str(), &c) == OCTOCAP_OK);
  testing::Calib calib(c);
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open((sample + "/keypoints").c_str(), OCTOCAP_LAYOUT_AUTO, &rec) == OCTOCAP_OK);
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.vmc_port = port;
  testing::Session s = testing::make_session(calib.get(), cfg);
  std::vector<octocap_keypoint2d_t> buf(4096);
  uint32_t people[8], n = 0;
  // Each received bone's position against the joint octocap solved there (Unity's frame, metres).
  const std::pair<const char*, int> at_head_of[] = {
      {"Spine", OCTOCAP_BONE_TORSO},           {"Neck", OCTOCAP_BONE_HEAD},
      {"LeftUpperArm", OCTOCAP_BONE_L_UPPER_ARM}, {"LeftLowerArm", OCTOCAP_BONE_L_LOWER_ARM},
      {"RightUpperArm", OCTOCAP_BONE_R_UPPER_ARM}, {"RightLowerArm", OCTOCAP_BONE_R_LOWER_ARM},
      {"LeftUpperLeg", OCTOCAP_BONE_L_UPPER_LEG}, {"LeftLowerLeg", OCTOCAP_BONE_L_LOWER_LEG},
      {"RightUpperLeg", OCTOCAP_BONE_R_UPPER_LEG}, {"RightLowerLeg", OCTOCAP_BONE_R_LOWER_LEG},
      {"LeftFoot", OCTOCAP_BONE_L_FOOT},       {"RightFoot", OCTOCAP_BONE_R_FOOT}};
  double worst = 0;
  for (uint32_t f = 0; f < 30; f += 3) {
    REQUIRE(octocap_recording_read_frame(rec, f, buf.data(), 4096, &n, people, 5) == OCTOCAP_OK);
    REQUIRE(octocap_session_solve_keypoints(s.get(), buf.data(), people, 5, f * 33333) == OCTOCAP_OK);
    std::vector<uint8_t> packet(65536);
    const ssize_t got = recv(sock, packet.data(), packet.size(), 0);
    REQUIRE(got > 0);
    packet.resize(static_cast<size_t>(got));
    const auto rebuilt = rebuild_pose(parse_bundle(packet));
    octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
    REQUIRE(octocap_session_get_bones(s.get(), OCTOCAP_FRAME_UNITY, bones, OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
    for (const auto& [name, bone] : at_head_of) {
      INFO("frame " << f << ", " << name);
      REQUIRE(bones[bone].valid);
      REQUIRE(rebuilt.count(name));
      const Eigen::Vector3d solved(bones[bone].head_position[0], bones[bone].head_position[1],
                                   bones[bone].head_position[2]);
      const double error = (rebuilt.at(name) - solved).norm();
      CHECK(error < 0.02);  // the rest pose's straight hips and shoulders against the solved ones: millimetres
      worst = std::max(worst, error);
    }
    // The head bone ends at the head joint: Head is half way along it.
    const Eigen::Vector3d neck(bones[OCTOCAP_BONE_HEAD].head_position[0], bones[OCTOCAP_BONE_HEAD].head_position[1],
                               bones[OCTOCAP_BONE_HEAD].head_position[2]);
    CHECK(std::abs((rebuilt.at("Head") - neck).norm() - bones[OCTOCAP_BONE_HEAD].length_m / 2) < 0.005);
  }
  INFO("worst joint " << worst * 1000 << " mm");
  CHECK(worst > 0);  // compared for real
  octocap_recording_destroy(rec);
  close(sock);
}

TEST_CASE("VMC output with several people: a port each, kept while tracked, OK 0 once when the person goes",
          "[vmc][people]") {
  // Two receivers on consecutive ports: VMC port P for the first slot, P + 1 for the second.
  int socks[2] = {-1, -1};
  uint16_t port = 0;
  for (int attempt = 0; attempt < 20 && socks[1] < 0; ++attempt) {
    if (socks[0] >= 0) close(socks[0]);
    socks[0] = bind_udp(0, port);
    uint16_t next = 0;
    if (port < 65535) socks[1] = bind_udp(static_cast<uint16_t>(port + 1), next);
  }
  REQUIRE(socks[1] >= 0);

  // Two real motions side by side, five cameras; the first person walks off after frame 11.
  octocap::internal::synth::RigOptions rig;
  const octocap::internal::Calibration truth_calib = octocap::internal::synth::make_camera_ring(rig);
  const auto crowd = octocap::internal::synth::make_crowd(2, 18);
  testing::TempDir dir;
  octocap::internal::write_calibration_toml(truth_calib, dir.file("calibration.toml"));
  octocap_calibration_t* c = nullptr;
  REQUIRE(octocap_calibration_load(dir.file("calibration.toml").c_str(), &c) == OCTOCAP_OK);
  testing::Calib calib(c);
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.max_people = 2;
  cfg.vmc_port = port;
  testing::Session s = testing::make_session(calib.get(), cfg);

  std::mt19937 rng(3);
  uint32_t slot_id[2] = {0, 0};  // the person each port drives
  int gone_slot = -1;
  for (size_t f = 0; f < 18; ++f) {
    INFO("frame " << f);
    const bool both = f < 12;
    std::vector<std::vector<Eigen::Vector3d>> now{both ? crowd[0][f] : std::vector<Eigen::Vector3d>{}, crowd[1][f]};
    const auto flat = octocap::internal::synth::flatten(
        octocap::internal::synth::observe_crowd(truth_calib, now, octocap::internal::LayoutId::body25, {}, rng).views);
    REQUIRE(octocap_session_solve_keypoints(s.get(), reinterpret_cast<const octocap_keypoint2d_t*>(flat.xyc.data()),
                                            flat.people_per_view.data(), 5, static_cast<int64_t>(f) * 33333) ==
            OCTOCAP_OK);
    octocap_frame_t* frame = nullptr;
    REQUIRE(octocap_session_get_frame(s.get(), &frame) == OCTOCAP_OK);
    octocap_frame_summary_t sum{};
    sum.struct_size = sizeof sum;
    REQUIRE(octocap_frame_get_summary(frame, &sum) == OCTOCAP_OK);
    REQUIRE(sum.person_count == (both ? 2u : 1u));
    std::map<uint32_t, std::vector<octocap_bone_pose_t>> bones;  // by person id, Unity's frame
    for (uint32_t i = 0; i < sum.person_count; ++i) {
      octocap_person_t p{};
      p.struct_size = sizeof p;
      REQUIRE(octocap_frame_get_person(frame, i, &p) == OCTOCAP_OK);
      std::vector<octocap_bone_pose_t> b(OCTOCAP_BONE_COUNT);
      uint32_t n = 0;
      REQUIRE(octocap_frame_get_bones(frame, i, OCTOCAP_FRAME_UNITY, b.data(), OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
      bones[p.id] = b;
    }
    octocap_frame_release(frame);

    for (int slot = 0; slot < 2; ++slot) {
      INFO("port " << port + slot);
      const std::vector<OscMessage> bundle = next_bundle(socks[slot]);
      if (slot == gone_slot) {  // said once, then silent
        CHECK(bundle.empty());
        continue;
      }
      REQUIRE_FALSE(bundle.empty());
      const OscMessage* ok = nullptr;
      const OscMessage* root = nullptr;
      for (const OscMessage& m : bundle) {
        if (m.address == "/VMC/Ext/OK") ok = &m;
        if (m.address == "/VMC/Ext/Root/Pos") root = &m;
      }
      REQUIRE(ok);
      if (ok->ints.at(0) == 0) {  // this port's person went
        CHECK(f == 12);
        CHECK_FALSE(root);
        CHECK(bones.count(slot_id[slot]) == 0);
        gone_slot = slot;
        continue;
      }
      // The root of exactly one person of the frame, the same person as on this port before.
      REQUIRE(root);
      uint32_t who = 0;
      for (const auto& [id, b] : bones)
        if (root->floats.at(0) == b[0].head_position[0] && root->floats.at(1) == b[0].head_position[1] &&
            root->floats.at(6) == b[0].global_rotation.w)
          who = id;
      REQUIRE(who != 0);
      if (slot_id[slot] != 0) CHECK(who == slot_id[slot]);
      slot_id[slot] = who;
    }
    CHECK(slot_id[0] != slot_id[1]);
  }
  CHECK(gone_slot >= 0);
  close(socks[0]);
  close(socks[1]);

  // Ports for every slot must exist: 16 people from port 65530 would run past 65535.
  cfg.max_people = 0;
  cfg.vmc_port = 65530;
  octocap_session_t* bad = nullptr;
  CHECK(octocap_session_create(&cfg, calib.get(), &bad) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(std::string(octocap_last_error()).find("65535") != std::string::npos);
  CHECK(bad == nullptr);
}

TEST_CASE("VMC output: a real OSC receiver gets every bone as octocap solved it, in Unity's frame", "[vmc]") {
  const int sock = socket(AF_INET, SOCK_DGRAM, 0);
  REQUIRE(sock >= 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  REQUIRE(bind(sock, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
  socklen_t len = sizeof addr;
  REQUIRE(getsockname(sock, reinterpret_cast<sockaddr*>(&addr), &len) == 0);
  timeval tv{2, 0};
  setsockopt(sock, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);

  const std::string sample = std::string(OCTOCAP_SOURCE_DIR) + "/data/sample";
  octocap_calibration_t* c = nullptr;
  REQUIRE(octocap_calibration_load((sample + "/calibration.toml").c_str(), &c) == OCTOCAP_OK);
  testing::Calib calib(c);
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open((sample + "/keypoints").c_str(), OCTOCAP_LAYOUT_AUTO, &rec) == OCTOCAP_OK);
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.vmc_port = ntohs(addr.sin_port);
  testing::Session s = testing::make_session(calib.get(), cfg);
  std::vector<octocap_keypoint2d_t> buf(4096);
  uint32_t people[8], n = 0;
  for (uint32_t f = 0; f < 5; ++f) {
    REQUIRE(octocap_recording_read_frame(rec, f, buf.data(), 4096, &n, people, 5) == OCTOCAP_OK);
    REQUIRE(octocap_session_solve_keypoints(s.get(), buf.data(), people, 5, f * 33333) == OCTOCAP_OK);
    std::vector<uint8_t> packet(65536);
    const ssize_t got = recv(sock, packet.data(), packet.size(), 0);
    REQUIRE(got > 0);
    packet.resize(static_cast<size_t>(got));
    const auto messages = parse_bundle(packet);

    octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
    REQUIRE(octocap_session_get_bones(s.get(), OCTOCAP_FRAME_UNITY, bones, OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
    std::map<std::string, OscMessage> by_bone;
    bool ok = false, root = false;
    for (const auto& m : messages) {
      if (m.address == "/VMC/Ext/Bone/Pos") by_bone[m.name] = m;
      if (m.address == "/VMC/Ext/OK") ok = m.ints.at(0) == 1;
      if (m.address == "/VMC/Ext/Root/Pos") {
        root = true;
        REQUIRE(m.floats.size() == 7);
        for (int k = 0; k < 3; ++k) REQUIRE(m.floats[k] == bones[0].head_position[k]);
        REQUIRE(m.floats[6] == bones[0].global_rotation.w);
      }
    }
    REQUIRE(ok);
    REQUIRE(root);
    // Every bone the frame solved, and only those: the sample is BODY_25, which has no hand points.
    uint32_t valid = 0;
    for (const octocap_bone_pose_t& b : bones) valid += b.valid;
    REQUIRE(valid == OCTOCAP_BONE_COUNT - 2);
    // The torso goes out as Spine, Chest and UpperChest, the head bone as Neck and Head: three names more.
    REQUIRE(by_bone.size() == valid + 3);
    REQUIRE(by_bone.count("RightHand") == 0);
    for (const char* name : {"Hips", "Spine", "Chest", "UpperChest", "Neck", "Head"}) CHECK(by_bone.count(name) == 1);
    const Eigen::Quaterniond back =
        quaternion(by_bone.at("Spine")) * quaternion(by_bone.at("Chest")) * quaternion(by_bone.at("UpperChest"));
    const octocap_quat_t& torso = bones[OCTOCAP_BONE_TORSO].local_rotation;
    CHECK(back.angularDistance(Eigen::Quaterniond(torso.w, torso.x, torso.y, torso.z)) < 1e-5);
    const std::pair<const char*, int> checks[] = {{"LeftLowerArm", OCTOCAP_BONE_L_LOWER_ARM},
                                                  {"RightUpperLeg", OCTOCAP_BONE_R_UPPER_LEG},
                                                  {"LeftShoulder", OCTOCAP_BONE_L_SHOULDER}};
    for (const auto& [name, bone] : checks) {
      INFO(name);
      const OscMessage& m = by_bone.at(name);
      REQUIRE(m.floats.size() == 7);
      REQUIRE(m.floats[3] == bones[bone].local_rotation.x);
      REQUIRE(m.floats[4] == bones[bone].local_rotation.y);
      REQUIRE(m.floats[5] == bones[bone].local_rotation.z);
      REQUIRE(m.floats[6] == bones[bone].local_rotation.w);
    }
    // The lower arm hangs off the upper arm's tail: its local position is the upper arm's length along it.
    const OscMessage& lower = by_bone.at("LeftLowerArm");
    REQUIRE(std::abs(lower.floats[0]) == bones[OCTOCAP_BONE_L_UPPER_ARM].length_m);
  }
  octocap_recording_destroy(rec);
  close(sock);
}
