#include "stream/dds_security.h"

#include <filesystem>

namespace octocap::internal {
namespace {

namespace fs = std::filesystem;

std::string file_uri(const fs::path& p) { return "file:" + fs::absolute(p).lexically_normal().string(); }

}  // namespace

void set_security_qos(dds_qos_t* qos, const SecureIdentity& id) {
  const fs::path keystore(id.keystore), folder(id.folder);
  dds_qset_prop(qos, "dds.sec.auth.library.path", "dds_security_auth");
  dds_qset_prop(qos, "dds.sec.auth.library.init", "init_authentication");
  dds_qset_prop(qos, "dds.sec.auth.library.finalize", "finalize_authentication");
  dds_qset_prop(qos, "dds.sec.crypto.library.path", "dds_security_crypto");
  dds_qset_prop(qos, "dds.sec.crypto.library.init", "init_crypto");
  dds_qset_prop(qos, "dds.sec.crypto.library.finalize", "finalize_crypto");
  dds_qset_prop(qos, "dds.sec.access.library.path", "dds_security_ac");
  dds_qset_prop(qos, "dds.sec.access.library.init", "init_access_control");
  dds_qset_prop(qos, "dds.sec.access.library.finalize", "finalize_access_control");
  dds_qset_prop(qos, "dds.sec.auth.identity_ca", file_uri(keystore / "ca.pem").c_str());
  dds_qset_prop(qos, "dds.sec.auth.identity_certificate", file_uri(folder / "cert.pem").c_str());
  dds_qset_prop(qos, "dds.sec.auth.private_key", file_uri(folder / "key.pem").c_str());
  dds_qset_prop(qos, "dds.sec.access.permissions_ca", file_uri(keystore / "ca.pem").c_str());
  dds_qset_prop(qos, "dds.sec.access.governance", file_uri(keystore / "governance.p7s").c_str());
  dds_qset_prop(qos, "dds.sec.access.permissions", file_uri(folder / "permissions.p7s").c_str());
}

}  // namespace octocap::internal
