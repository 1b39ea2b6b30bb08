// Keeps Cyclone DDS on loopback with no multicast (as tests and benchmarks must), and a domain per process.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <unistd.h>

namespace testing {

inline uint32_t loopback_dds_domain() {
  static const uint32_t domain = [] {
    setenv("CYCLONEDDS_URI",
           "<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface name=\"lo\"/></Interfaces>"
           "<AllowMulticast>false</AllowMulticast></General><Discovery><Peers><Peer address=\"127.0.0.1\"/></Peers>"
           "<ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>50</MaxAutoParticipantIndex>"
           "</Discovery></Domain></CycloneDDS>",
           1);
    return static_cast<uint32_t>(1 + getpid() % 200);
  }();
  return domain;
}

}  // namespace testing
