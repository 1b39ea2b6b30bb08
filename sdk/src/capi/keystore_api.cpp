// DDS Security keystores (stream/keystore.h, stream/identity_check.h) through the C ABI.
#include "capi/boundary.h"
#include "stream/identity_check.h"
#include "stream/keystore.h"

using namespace octocap::internal;

namespace {

SecurityRole role_of(octocap_security_role_t role) {
  if (role != OCTOCAP_ROLE_NODE && role != OCTOCAP_ROLE_HUB && role != OCTOCAP_ROLE_VIEWER)
    throw Error(Errc::invalid_argument, "role must be OCTOCAP_ROLE_NODE, OCTOCAP_ROLE_HUB or OCTOCAP_ROLE_VIEWER");
  return static_cast<SecurityRole>(role);
}

}  // namespace

extern "C" {

octocap_result_t octocap_keystore_create(const char* dir, uint32_t valid_days) {
  return capi::guard([&] {
    capi::require(dir, "dir");
    create_keystore(dir, valid_days);
  });
}

octocap_result_t octocap_keystore_add_identity(const char* dir, const char* name, octocap_security_role_t role,
                                               uint32_t valid_days) {
  return capi::guard([&] {
    capi::require(dir, "dir");
    capi::require(name, "name");
    add_identity(dir, name, role_of(role), valid_days);
  });
}

octocap_result_t octocap_keystore_check_identity(const char* identity_dir, octocap_security_role_t* role) {
  return capi::guard([&] {
    capi::require(identity_dir, "identity_dir");
    const SecureIdentity id = check_identity(identity_dir);
    if (!role) return;
    for (SecurityRole r : {SecurityRole::node, SecurityRole::hub, SecurityRole::viewer})
      if (id.role == role_name(r)) {
        *role = static_cast<octocap_security_role_t>(r);
        return;
      }
    throw Error(Errc::parse, id.folder + "/permissions.p7s: a grant of no octocap role");
  });
}

}  // extern "C"
