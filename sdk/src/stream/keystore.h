// A studio keystore for DDS Security: one certificate authority (CA) signs every participant's identity, the shared
// governance (nobody unauthenticated joins, everything encrypted) and each identity's permissions (what its role may
// write and read). Made with OpenSSL; laid out as Cyclone DDS's security plugins read it:
//   DIR/ca.pem  DIR/ca.key.pem (the CA's key: keep it off the capture network)  DIR/governance.xml|.p7s
//   DIR/NAME/cert.pem  DIR/NAME/key.pem  DIR/NAME/permissions.xml|.p7s
// Private keys and folders are readable by their owner only.
#pragma once
#include <cstdint>
#include <string>

namespace octocap::internal {

// node: publishes 2D keypoints (a capture node). hub: reads keypoints, publishes skeletons (octocap live, solve
// --publish). viewer: reads skeletons (the viewer, the stream echo, an engine's subscriber).
enum class SecurityRole : int { node = 0, hub = 1, viewer = 2 };

const char* role_name(SecurityRole role);

// Creates the CA and the signed governance in a new or empty folder `dir`. Throws Error(invalid_argument) for a
// folder that holds a keystore already (its CA would be lost), Error(io) naming a file that cannot be written.
void create_keystore(const std::string& dir, uint32_t valid_days);

// Creates DIR/NAME: a key, a certificate the CA signs (subject "CN=NAME,O=octocap") and the role's permissions,
// signed. NAME: 1-64 letters, digits, '-', '_' or '.'. Throws Error(invalid_argument) for an identity that exists.
void add_identity(const std::string& dir, const std::string& name, SecurityRole role, uint32_t valid_days);

// The subject name octocap gives an identity NAME, as the permissions file and Cyclone write it.
std::string identity_subject(const std::string& name);

}  // namespace octocap::internal
