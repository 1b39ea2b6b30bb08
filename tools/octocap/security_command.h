// octocap security: a studio's DDS Security keystore (docs/security.md), made in one command per step.
#pragma once
#include <string>

namespace CLI {
class App;
}

struct SecurityOptions {
  std::string keystore, name, role, identity;
  unsigned days = 0;  // 0: 10 years for a keystore, 1 year for an identity
  bool init = false, add = false, check = false;
};

// Adds `security init|add|check` to `app`; returns the `security` subcommand.
CLI::App* add_security_commands(CLI::App& app, SecurityOptions& options);
int run_security(const SecurityOptions& options);
