// A keystore identity folder (see keystore.h) checked before a participant uses it: what would fail inside Cyclone's
// security plugins, which say only "creating the participant failed", fails here naming the file and the cause.
#pragma once
#include <string>

namespace octocap::internal {

struct SecureIdentity {
  std::string keystore;   // the folder with ca.pem and governance.p7s
  std::string folder;     // keystore/NAME
  std::string subject;    // "CN=NAME,O=octocap"
  std::string role;       // from the permissions' grant name: "node", "hub", "viewer" ("" unknown)
};

// Throws Error(io) for a missing file, Error(parse) for one that is not what it should be, Error(invalid_argument)
// for an identity that is expired, not yet valid, not signed by the keystore's CA, whose key is not its
// certificate's, or whose permissions name another subject.
SecureIdentity check_identity(const std::string& identity_folder);

}  // namespace octocap::internal
