#include "security_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "octocap/octocap.h"

namespace {

constexpr unsigned kKeystoreDays = 3650;
constexpr unsigned kIdentityDays = 365;

octocap_security_role_t role_of(const std::string& role) {
  return role == "node" ? OCTOCAP_ROLE_NODE : role == "hub" ? OCTOCAP_ROLE_HUB : OCTOCAP_ROLE_VIEWER;
}

const char* role_text(octocap_security_role_t role) {
  switch (role) {
    case OCTOCAP_ROLE_NODE: return "node (publishes 2D keypoints)";
    case OCTOCAP_ROLE_HUB: return "hub (reads keypoints, publishes skeletons)";
    case OCTOCAP_ROLE_VIEWER: return "viewer (reads skeletons)";
  }
  return "?";
}

int failed(const char* what) {
  std::fprintf(stderr, "octocap security %s: %s\n", what, octocap_last_error());
  return 1;
}

}  // namespace

CLI::App* add_security_commands(CLI::App& app, SecurityOptions& o) {
  CLI::App* sec = app.add_subcommand("security", "DDS Security: a keystore that closes the capture network to everyone outside it (docs/security.md)");
  sec->require_subcommand(1);
  CLI::App* init = sec->add_subcommand("init", "Make a keystore: its certificate authority and the signed governance (everyone authenticated, everything encrypted)");
  init->add_option("KEYSTORE", o.keystore, "The keystore's folder (new or empty)")->required();
  init->add_option("--days", o.days, "Days the CA is valid (default 3650)")->check(CLI::Range(1, 36500));
  init->callback([&o] { o.init = true; });
  CLI::App* add = sec->add_subcommand("add", "Add an identity: a key, a certificate the CA signs, and its role's permissions");
  add->add_option("KEYSTORE", o.keystore, "The keystore's folder")->required()->check(CLI::ExistingDirectory);
  add->add_option("NAME", o.name, "The identity's name (its folder KEYSTORE/NAME is what --dds-security takes)")->required();
  add->add_option("--role", o.role, "node: publishes 2D keypoints (detect --live); hub: reads keypoints, publishes skeletons (live, solve --publish); viewer: reads skeletons (the viewer, a game)")
      ->required()->check(CLI::IsMember({"node", "hub", "viewer"}));
  add->add_option("--days", o.days, "Days the identity is valid (default 365)")->check(CLI::Range(1, 36500));
  add->callback([&o] { o.add = true; });
  CLI::App* check = sec->add_subcommand("check", "Check an identity folder as a participant does before it joins");
  check->add_option("IDENTITY", o.identity, "KEYSTORE/NAME")->required();
  check->callback([&o] { o.check = true; });
  return sec;
}

int run_security(const SecurityOptions& o) {
  if (o.init) {
    if (octocap_keystore_create(o.keystore.c_str(), o.days ? o.days : kKeystoreDays) != OCTOCAP_OK) return failed("init");
    std::printf("keystore %s: ca.pem, governance.p7s; ca.key.pem signs identities: keep it off the capture machines\n"
                "next: octocap security add %s NAME --role node|hub|viewer\n", o.keystore.c_str(), o.keystore.c_str());
    return 0;
  }
  if (o.add) {
    const octocap_security_role_t role = role_of(o.role);
    if (octocap_keystore_add_identity(o.keystore.c_str(), o.name.c_str(), role, o.days ? o.days : kIdentityDays) !=
        OCTOCAP_OK)
      return failed("add");
    std::printf("identity %s/%s: %s; give it with --dds-security %s/%s\n", o.keystore.c_str(), o.name.c_str(),
                role_text(role), o.keystore.c_str(), o.name.c_str());
    return 0;
  }
  octocap_security_role_t role = OCTOCAP_ROLE_VIEWER;
  if (octocap_keystore_check_identity(o.identity.c_str(), &role) != OCTOCAP_OK) return failed("check");
  std::printf("identity %s: valid, %s\n", o.identity.c_str(), role_text(role));
  return 0;
}
