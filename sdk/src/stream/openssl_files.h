// OpenSSL objects owned by unique_ptr, and the PEM and S/MIME files of a keystore read and written with them. Every
// failure is an Error naming the file and OpenSSL's reason.
#pragma once
#include <openssl/evp.h>
#include <openssl/pkcs7.h>
#include <openssl/x509.h>

#include <memory>
#include <string>

namespace octocap::internal {

struct OpenSslFree {
  void operator()(EVP_PKEY* p) const { EVP_PKEY_free(p); }
  void operator()(X509* p) const { X509_free(p); }
  void operator()(PKCS7* p) const { PKCS7_free(p); }
  void operator()(BIO* p) const { BIO_free(p); }
  void operator()(X509_STORE* p) const { X509_STORE_free(p); }
};
using KeyPtr = std::unique_ptr<EVP_PKEY, OpenSslFree>;
using CertPtr = std::unique_ptr<X509, OpenSslFree>;

// OpenSSL's queued errors as one line (and the queue emptied).
std::string openssl_reason();

KeyPtr read_private_key(const std::string& path);
CertPtr read_certificate(const std::string& path);
// Writes a file readable (and writable) by its owner only.
void write_private_key(const std::string& path, EVP_PKEY* key);
void write_certificate(const std::string& path, X509* cert);
void write_text(const std::string& path, const std::string& text);
std::string read_text(const std::string& path);

// `text` signed by `signer` as a clear-signed S/MIME message (what `openssl smime -sign -text` writes, and what the DDS
// Security plugins read governance and permissions from).
void write_signed(const std::string& path, const std::string& text, X509* signer, EVP_PKEY* key);
// The content of a clear-signed S/MIME file, after checking its signature chains to `ca`; throws Error(invalid_argument)
// naming the file when it does not.
std::string read_signed(const std::string& path, X509* ca);

// "CN=hub,O=octocap": RFC 2253 order, as DDS Security's permissions name subjects.
std::string subject_of(X509* cert);

}  // namespace octocap::internal
