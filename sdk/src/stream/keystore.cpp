#include "stream/keystore.h"

#include <openssl/rand.h>
#include <openssl/x509v3.h>
#include <sys/stat.h>

#include <ctime>
#include <filesystem>

#include "core/error.h"
#include "stream/openssl_files.h"
#include "stream/topics.h"

namespace octocap::internal {
namespace {

namespace fs = std::filesystem;

constexpr const char* kOrganization = "octocap";
// DDS domain ids a keystore covers: 0 .. 230, every id Cyclone's security plugins parse (its access control refuses a
// range reaching 231 or 232, which RTPS port mapping allows), so one keystore serves every domain a studio uses.
constexpr int kMaxDomain = 230;

void check_days(uint32_t valid_days) {
  if (valid_days < 1 || valid_days > 36500)
    throw Error(Errc::invalid_argument, "valid days must be 1 .. 36500 (got " + std::to_string(valid_days) + ")");
}

KeyPtr new_key() {
  // P-256: the curve both DDS Security's built-in authentication and Cyclone's plugin accept (with RSA-2048).
  KeyPtr key(EVP_EC_gen("P-256"));
  if (!key) throw Error(Errc::internal, "making a key failed: " + openssl_reason());
  return key;
}

void add_extension(X509* cert, X509* issuer, int nid, const char* value) {
  X509V3_CTX ctx;
  X509V3_set_ctx_nodb(&ctx);
  X509V3_set_ctx(&ctx, issuer, cert, nullptr, nullptr, 0);
  X509_EXTENSION* ext = X509V3_EXT_conf_nid(nullptr, &ctx, nid, value);
  if (!ext || X509_add_ext(cert, ext, -1) != 1) {
    X509_EXTENSION_free(ext);
    throw Error(Errc::internal, "certificate extension failed: " + openssl_reason());
  }
  X509_EXTENSION_free(ext);
}

// A certificate for `key` named CN=`common_name`,O=octocap, valid from now for `valid_days`, signed by `issuer_key`
// (itself when `issuer` is null: the CA).
CertPtr new_certificate(EVP_PKEY* key, const std::string& common_name, uint32_t valid_days, X509* issuer,
                        EVP_PKEY* issuer_key) {
  CertPtr cert(X509_new());
  unsigned char serial[16];
  if (!cert || RAND_bytes(serial, sizeof serial) != 1) throw Error(Errc::internal, "certificate: " + openssl_reason());
  serial[0] &= 0x7f;  // a positive serial number
  BIGNUM* bn = BN_bin2bn(serial, sizeof serial, nullptr);
  BN_to_ASN1_INTEGER(bn, X509_get_serialNumber(cert.get()));
  BN_free(bn);
  X509_set_version(cert.get(), 2);
  X509_gmtime_adj(X509_getm_notBefore(cert.get()), 0);
  X509_time_adj_ex(X509_getm_notAfter(cert.get()), static_cast<int>(valid_days), 0, nullptr);
  X509_set_pubkey(cert.get(), key);
  // Added O then CN: printed in RFC 2253 order that is "CN=...,O=octocap", as the permissions file names it.
  X509_NAME* name = X509_get_subject_name(cert.get());
  X509_NAME_add_entry_by_txt(name, "O", MBSTRING_UTF8, reinterpret_cast<const unsigned char*>(kOrganization), -1, -1, 0);
  X509_NAME_add_entry_by_txt(name, "CN", MBSTRING_UTF8, reinterpret_cast<const unsigned char*>(common_name.c_str()),
                             -1, -1, 0);
  X509* signer = issuer ? issuer : cert.get();
  X509_set_issuer_name(cert.get(), X509_get_subject_name(signer));
  if (!issuer) {
    add_extension(cert.get(), signer, NID_basic_constraints, "critical,CA:TRUE");
    add_extension(cert.get(), signer, NID_key_usage, "critical,keyCertSign,cRLSign,digitalSignature");
  } else {
    add_extension(cert.get(), signer, NID_basic_constraints, "critical,CA:FALSE");
    add_extension(cert.get(), signer, NID_key_usage, "critical,digitalSignature,keyAgreement");
  }
  add_extension(cert.get(), signer, NID_subject_key_identifier, "hash");
  if (X509_sign(cert.get(), issuer_key ? issuer_key : key, EVP_sha256()) <= 0)
    throw Error(Errc::internal, "signing the certificate failed: " + openssl_reason());
  return cert;
}

std::string xml_time(std::time_t t) {
  char buf[32];
  std::tm tm{};
  gmtime_r(&t, &tm);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return buf;
}

std::string domains() {
  return "<domains><id_range><min>0</min><max>" + std::to_string(kMaxDomain) + "</max></id_range></domains>";
}

// Nobody unauthenticated joins; discovery, liveliness, every topic's metadata and data are encrypted, and who may
// write or read a topic is checked against the permissions.
std::string governance_xml() {
  return std::string(
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<dds xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
             "xsi:noNamespaceSchemaLocation=\"http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd\">\n"
             "  <domain_access_rules>\n    <domain_rule>\n      ") +
         domains() +
         "\n"
         "      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>\n"
         "      <enable_join_access_control>true</enable_join_access_control>\n"
         "      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>\n"
         "      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>\n"
         "      <rtps_protection_kind>ENCRYPT</rtps_protection_kind>\n"
         "      <topic_access_rules>\n        <topic_rule>\n"
         "          <topic_expression>*</topic_expression>\n"
         "          <enable_discovery_protection>true</enable_discovery_protection>\n"
         "          <enable_liveliness_protection>true</enable_liveliness_protection>\n"
         "          <enable_read_access_control>true</enable_read_access_control>\n"
         "          <enable_write_access_control>true</enable_write_access_control>\n"
         "          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>\n"
         "          <data_protection_kind>ENCRYPT</data_protection_kind>\n"
         "        </topic_rule>\n      </topic_access_rules>\n"
         "    </domain_rule>\n  </domain_access_rules>\n</dds>\n";
}

std::string topics_xml(std::initializer_list<const char*> suffixes) {
  std::string s = "<topics>";
  for (const char* suffix : suffixes) s += std::string("<topic>*") + suffix + "</topic>";
  return s + "</topics>";
}

// What each role writes and reads: the one table of who may do what on a studio network.
std::string role_rules(SecurityRole role) {
  switch (role) {
    case SecurityRole::node:
      return "<publish>" + topics_xml({kKeypointsTopicSuffix}) + "</publish>";
    case SecurityRole::hub:
      return "<publish>" + topics_xml({kDefinitionTopicSuffix, kPoseTopicSuffix, kPeopleTopicSuffix}) +
             "</publish><subscribe>" + topics_xml({kKeypointsTopicSuffix}) + "</subscribe>";
    case SecurityRole::viewer:
      return "<subscribe>" + topics_xml({kDefinitionTopicSuffix, kPoseTopicSuffix, kPeopleTopicSuffix}) +
             "</subscribe>";
  }
  throw Error(Errc::invalid_argument, "unknown security role " + std::to_string(static_cast<int>(role)));
}

std::string permissions_xml(const std::string& name, SecurityRole role, const std::string& rules, uint32_t valid_days) {
  const std::time_t now = std::time(nullptr);
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<dds xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
         "xsi:noNamespaceSchemaLocation=\"http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd\">\n"
         "  <permissions>\n    <grant name=\"" + name + "_" + role_name(role) + "\">\n"
         "      <subject_name>" + identity_subject(name) + "</subject_name>\n"
         "      <validity><not_before>" + xml_time(now - 60) + "</not_before><not_after>" +
         xml_time(now + static_cast<std::time_t>(valid_days) * 86400) + "</not_after></validity>\n"
         "      <allow_rule>" + domains() + rules + "</allow_rule>\n"
         "      <default>DENY</default>\n    </grant>\n  </permissions>\n</dds>\n";
}

void make_private_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(Errc::io, dir.string() + ": cannot be created (" + ec.message() + ")");
  fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace, ec);
  if (ec) throw Error(Errc::io, dir.string() + ": cannot be made private (" + ec.message() + ")");
}

bool valid_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || name == "." || name == "..") return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') return false;
  return true;
}

}  // namespace

const char* role_name(SecurityRole role) {
  switch (role) {
    case SecurityRole::node: return "node";
    case SecurityRole::hub: return "hub";
    case SecurityRole::viewer: return "viewer";
  }
  return "unknown";
}

std::string identity_subject(const std::string& name) { return "CN=" + name + ",O=" + kOrganization; }

void create_keystore(const std::string& dir, uint32_t valid_days) {
  check_days(valid_days);
  const fs::path root(dir);
  if (fs::exists(root / "ca.pem") || fs::exists(root / "ca.key.pem"))
    throw Error(Errc::invalid_argument, dir + " holds a keystore already (ca.pem): its identities would be orphaned");
  make_private_dir(root);
  KeyPtr key = new_key();
  CertPtr ca = new_certificate(key.get(), "octocap CA", valid_days, nullptr, nullptr);
  write_private_key((root / "ca.key.pem").string(), key.get());
  write_certificate((root / "ca.pem").string(), ca.get());
  const std::string governance = governance_xml();
  write_text((root / "governance.xml").string(), governance);
  write_signed((root / "governance.p7s").string(), governance, ca.get(), key.get());
}

void add_identity(const std::string& dir, const std::string& name, SecurityRole role, uint32_t valid_days) {
  check_days(valid_days);
  if (!valid_name(name))
    throw Error(Errc::invalid_argument, "identity name '" + name + "': 1 to 64 letters, digits, '-', '_' or '.'");
  const fs::path root(dir);
  const std::string rules = role_rules(role);  // an unknown role fails before anything is written
  CertPtr ca = read_certificate((root / "ca.pem").string());
  KeyPtr ca_key = read_private_key((root / "ca.key.pem").string());
  const fs::path home = root / name;
  if (fs::exists(home / "cert.pem"))
    throw Error(Errc::invalid_argument, home.string() + " exists already: pick another name or remove it");
  make_private_dir(home);
  KeyPtr key = new_key();
  CertPtr cert = new_certificate(key.get(), name, valid_days, ca.get(), ca_key.get());
  write_private_key((home / "key.pem").string(), key.get());
  write_certificate((home / "cert.pem").string(), cert.get());
  const std::string permissions = permissions_xml(name, role, rules, valid_days);
  write_text((home / "permissions.xml").string(), permissions);
  write_signed((home / "permissions.p7s").string(), permissions, ca.get(), ca_key.get());
}

}  // namespace octocap::internal
