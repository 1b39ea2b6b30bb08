#include "stream/identity_check.h"

#include <openssl/x509.h>

#include <ctime>
#include <filesystem>

#include "core/error.h"
#include "stream/openssl_files.h"

namespace octocap::internal {
namespace {

namespace fs = std::filesystem;

std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const size_t a = text.find(open);
  if (a == std::string::npos) return "";
  const size_t b = text.find(close, a + open.size());
  return b == std::string::npos ? "" : text.substr(a + open.size(), b - a - open.size());
}

std::string asn1_time_text(const ASN1_TIME* t) {
  std::tm tm{};
  if (ASN1_TIME_to_tm(t, &tm) != 1) return "?";
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

void check_dates(X509* cert, const std::string& path) {
  if (X509_cmp_current_time(X509_get0_notAfter(cert)) <= 0)
    throw Error(Errc::invalid_argument, path + ": expired on " + asn1_time_text(X509_get0_notAfter(cert)) +
                                            " (make a new identity with `octocap security add`)");
  if (X509_cmp_current_time(X509_get0_notBefore(cert)) >= 0)
    throw Error(Errc::invalid_argument,
                path + ": not valid before " + asn1_time_text(X509_get0_notBefore(cert)) + " (is this clock right?)");
}

// The permissions' validity, "YYYY-MM-DDTHH:MM:SS" (UTC), against now: Cyclone refuses them silently otherwise.
void check_permission_dates(const std::string& xml, const std::string& path) {
  const auto parse = [](const std::string& s, std::time_t& out) {
    std::tm tm{};
    if (s.size() < 19 || !strptime(s.c_str(), "%Y-%m-%dT%H:%M:%S", &tm)) return false;
    out = timegm(&tm);
    return true;
  };
  std::time_t before = 0, after = 0;
  const std::string nb = between(xml, "<not_before>", "</not_before>"), na = between(xml, "<not_after>", "</not_after>");
  if (!parse(nb, before) || !parse(na, after)) throw Error(Errc::parse, path + ": no readable <validity> dates");
  const std::time_t now = std::time(nullptr);
  if (now > after) throw Error(Errc::invalid_argument, path + ": the permissions expired on " + na + " UTC");
  if (now < before) throw Error(Errc::invalid_argument, path + ": the permissions start on " + nb + " UTC");
}

}  // namespace

SecureIdentity check_identity(const std::string& identity_folder) {
  fs::path folder = fs::path(identity_folder).lexically_normal();
  if (!folder.has_filename()) folder = folder.parent_path();  // "keystore/hub/"
  if (identity_folder.empty() || !fs::is_directory(folder))
    throw Error(Errc::io, identity_folder + ": no such identity folder (make one with `octocap security add`)");
  const fs::path keystore = folder.parent_path().empty() ? fs::path(".") : folder.parent_path();
  for (const fs::path& p : {keystore / "ca.pem", keystore / "governance.p7s", folder / "cert.pem",
                            folder / "key.pem", folder / "permissions.p7s"})
    if (!fs::is_regular_file(p))
      throw Error(Errc::io, p.string() + ": not found (an identity folder is KEYSTORE/NAME, made by `octocap security`)");
  const std::string ca_path = (keystore / "ca.pem").string(), cert_path = (folder / "cert.pem").string();
  CertPtr ca = read_certificate(ca_path);
  check_dates(ca.get(), ca_path);
  CertPtr cert = read_certificate(cert_path);
  check_dates(cert.get(), cert_path);
  KeyPtr ca_key(X509_get_pubkey(ca.get()));
  if (!ca_key || X509_verify(cert.get(), ca_key.get()) != 1) {
    (void)openssl_reason();
    throw Error(Errc::invalid_argument, cert_path + ": not signed by the keystore's CA (" + ca_path + ")");
  }
  KeyPtr key = read_private_key((folder / "key.pem").string());
  if (X509_check_private_key(cert.get(), key.get()) != 1) {
    (void)openssl_reason();
    throw Error(Errc::invalid_argument, (folder / "key.pem").string() + ": not the key of " + cert_path);
  }
  (void)read_signed((keystore / "governance.p7s").string(), ca.get());
  const std::string permissions_path = (folder / "permissions.p7s").string();
  const std::string permissions = read_signed(permissions_path, ca.get());
  check_permission_dates(permissions, permissions_path);
  SecureIdentity id;
  id.keystore = keystore.string();
  id.folder = folder.string();
  id.subject = subject_of(cert.get());
  const std::string named = between(permissions, "<subject_name>", "</subject_name>");
  if (named != id.subject)
    throw Error(Errc::invalid_argument, permissions_path + ": grants '" + named + "', but " + cert_path + " is '" +
                                            id.subject + "'");
  const std::string grant = between(permissions, "<grant name=\"", "\"");
  const size_t underscore = grant.rfind('_');
  id.role = underscore == std::string::npos ? "" : grant.substr(underscore + 1);
  return id;
}

}  // namespace octocap::internal
