// The outputs a session can feed besides files (DDS streaming, VMC), as `octocap solve` and `octocap live` take them.
#pragma once
#include <cstdio>
#include <stdexcept>
#include <string>

#include "octocap/octocap.h"

struct OutputOptions {
  bool publish = false;
  std::string publish_qos = "live";
  unsigned domain = 0;
  std::string topic = "octocap";
  unsigned source_id = 1;
  unsigned vmc_port = 0;
  std::string vmc_host = "127.0.0.1";
  std::string dds_security;  // a keystore identity folder (octocap security add): every DDS participant secured
};

// A keystore identity folder into a C config's path field; a path that does not fit is refused, never cut.
template <size_t N>
void set_identity(char (&field)[N], const std::string& folder) {
  if (folder.size() >= N)
    throw std::runtime_error("--dds-security: the path is longer than " + std::to_string(N - 1) + " bytes");
  std::snprintf(field, N, "%s", folder.c_str());
}

inline void apply_outputs(const OutputOptions& o, octocap_session_config_t& cfg) {
  set_identity(cfg.stream_security, o.dds_security);
  cfg.vmc_port = o.vmc_port;
  std::snprintf(cfg.vmc_host, sizeof cfg.vmc_host, "%s", o.vmc_host.c_str());
  if (!o.publish) return;
  cfg.stream_enable = 1;
  cfg.stream_domain_id = o.domain;
  cfg.stream_qos = o.publish_qos == "record" ? OCTOCAP_QOS_RECORD : OCTOCAP_QOS_LIVE;
  cfg.stream_source_id = o.source_id;
  std::snprintf(cfg.stream_topic, sizeof cfg.stream_topic, "%s", o.topic.c_str());
}
