// Switching DDS Security on for one participant from a checked keystore identity (identity_check.h): its QoS names
// Cyclone's plugins and the identity's files, which leaves every other setting of the user's CYCLONEDDS_URI as it was.
#pragma once
#include <dds/dds.h>

#include "stream/identity_check.h"

namespace octocap::internal {

// Adds the security properties of `id` to a participant QoS.
void set_security_qos(dds_qos_t* qos, const SecureIdentity& id);

}  // namespace octocap::internal
