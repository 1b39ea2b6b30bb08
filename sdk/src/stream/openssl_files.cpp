#include "stream/openssl_files.h"

#include <openssl/err.h>
#include <openssl/pem.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace octocap::internal {
namespace {

using BioPtr = std::unique_ptr<BIO, OpenSslFree>;

BioPtr open_read(const std::string& path) {
  BioPtr bio(BIO_new_file(path.c_str(), "rb"));
  if (!bio) {
    ERR_clear_error();
    throw Error(Errc::io, path + ": cannot be read (" + std::string(std::strerror(errno)) + ")");
  }
  return bio;
}

// Created 0600 before anything is written, so a key is never readable by others, not even for a moment.
BioPtr open_write(const std::string& path, bool private_file) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, private_file ? 0600 : 0644);
  if (fd < 0) throw Error(Errc::io, path + ": cannot be written (" + std::string(std::strerror(errno)) + ")");
  if (private_file) ::fchmod(fd, 0600);
  FILE* f = ::fdopen(fd, "wb");
  if (!f) {
    ::close(fd);
    throw Error(Errc::io, path + ": cannot be written");
  }
  BioPtr bio(BIO_new_fp(f, BIO_CLOSE));
  if (!bio) {
    std::fclose(f);
    throw Error(Errc::out_of_memory, path + ": " + openssl_reason());
  }
  return bio;
}

void finish(BIO* bio, bool ok, const std::string& path) {
  if (!ok || BIO_flush(bio) != 1) throw Error(Errc::io, path + ": writing failed: " + openssl_reason());
}

}  // namespace

std::string openssl_reason() {
  std::string reason;
  while (const unsigned long e = ERR_get_error()) {
    char buf[256];
    ERR_error_string_n(e, buf, sizeof buf);
    if (!reason.empty()) reason += "; ";
    reason += buf;
  }
  return reason.empty() ? "no reason given" : reason;
}

KeyPtr read_private_key(const std::string& path) {
  BioPtr bio = open_read(path);
  KeyPtr key(PEM_read_bio_PrivateKey(bio.get(), nullptr, nullptr, nullptr));
  if (!key) throw Error(Errc::parse, path + ": not a PEM private key (" + openssl_reason() + ")");
  return key;
}

CertPtr read_certificate(const std::string& path) {
  BioPtr bio = open_read(path);
  CertPtr cert(PEM_read_bio_X509(bio.get(), nullptr, nullptr, nullptr));
  if (!cert) throw Error(Errc::parse, path + ": not a PEM certificate (" + openssl_reason() + ")");
  return cert;
}

void write_private_key(const std::string& path, EVP_PKEY* key) {
  BioPtr bio = open_write(path, true);
  finish(bio.get(), PEM_write_bio_PrivateKey(bio.get(), key, nullptr, nullptr, 0, nullptr, nullptr) == 1, path);
}

void write_certificate(const std::string& path, X509* cert) {
  BioPtr bio = open_write(path, false);
  finish(bio.get(), PEM_write_bio_X509(bio.get(), cert) == 1, path);
}

void write_text(const std::string& path, const std::string& text) {
  BioPtr bio = open_write(path, false);
  finish(bio.get(), BIO_write(bio.get(), text.data(), static_cast<int>(text.size())) == static_cast<int>(text.size()),
         path);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(Errc::io, path + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_signed(const std::string& path, const std::string& text, X509* signer, EVP_PKEY* key) {
  const int flags = PKCS7_DETACHED | PKCS7_TEXT;
  BioPtr content(BIO_new_mem_buf(text.data(), static_cast<int>(text.size())));
  std::unique_ptr<PKCS7, OpenSslFree> p7(PKCS7_sign(signer, key, nullptr, content.get(), flags));
  if (!p7) throw Error(Errc::internal, path + ": signing failed: " + openssl_reason());
  BioPtr again(BIO_new_mem_buf(text.data(), static_cast<int>(text.size())));
  BioPtr out = open_write(path, false);
  finish(out.get(), SMIME_write_PKCS7(out.get(), p7.get(), again.get(), flags) == 1, path);
}

std::string read_signed(const std::string& path, X509* ca) {
  BioPtr bio = open_read(path);
  BIO* content_raw = nullptr;
  std::unique_ptr<PKCS7, OpenSslFree> p7(SMIME_read_PKCS7(bio.get(), &content_raw));
  BioPtr content(content_raw);
  if (!p7) throw Error(Errc::parse, path + ": not a signed S/MIME document (" + openssl_reason() + ")");
  std::unique_ptr<X509_STORE, OpenSslFree> store(X509_STORE_new());
  X509_STORE_add_cert(store.get(), ca);
  BioPtr out(BIO_new(BIO_s_mem()));
  if (PKCS7_verify(p7.get(), nullptr, store.get(), content.get(), out.get(), PKCS7_TEXT) != 1)
    throw Error(Errc::invalid_argument, path + ": not signed by the keystore's CA (" + openssl_reason() + ")");
  char* data = nullptr;
  const long n = BIO_get_mem_data(out.get(), &data);
  return std::string(data, static_cast<size_t>(n));
}

std::string subject_of(X509* cert) {
  BioPtr out(BIO_new(BIO_s_mem()));
  X509_NAME_print_ex(out.get(), X509_get_subject_name(cert), 0, XN_FLAG_RFC2253);
  char* data = nullptr;
  const long n = BIO_get_mem_data(out.get(), &data);
  return std::string(data, static_cast<size_t>(n));
}

}  // namespace octocap::internal
