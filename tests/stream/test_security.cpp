// DDS Security keystores (octocap_keystore_*, octocap security): what they make, what they refuse, and that a
// participant's identity is checked with errors that name the file and the cause. Then a capture node process and
// this process as its hub over secured loopback DDS: the keystore's node is heard, a foreign keystore's node and an
// unsecured one are not. (Skeleton streams between processes: scripts/check-security.sh.)
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <openssl/pem.h>
#include <openssl/x509.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "octocap/octocap.h"

#ifdef OCTOCAP_HAVE_DDS
#include "capture/camera_spec.h"
#include "core/clock.h"
#include "stream/keypoint_publisher.h"
#include "stream/remote_feed.h"
#include "support/child_process.h"
#include "support/live_helpers.h"
#include "support/loopback_dds.h"
#include "support/run_command.h"
#endif

using Catch::Matchers::ContainsSubstring;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    char pattern[] = "/tmp/octocap-keystore-XXXXXX";
    path = mkdtemp(pattern);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

unsigned mode_of(const std::string& path) {
  struct stat st{};
  REQUIRE(stat(path.c_str(), &st) == 0);
  return st.st_mode & 0777;
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A keystore with a hub, a viewer and a node.
void make_studio(const std::string& dir) {
  REQUIRE(octocap_keystore_create(dir.c_str(), 30) == OCTOCAP_OK);
  REQUIRE(octocap_keystore_add_identity(dir.c_str(), "hub", OCTOCAP_ROLE_HUB, 30) == OCTOCAP_OK);
  REQUIRE(octocap_keystore_add_identity(dir.c_str(), "viewer", OCTOCAP_ROLE_VIEWER, 30) == OCTOCAP_OK);
  REQUIRE(octocap_keystore_add_identity(dir.c_str(), "booth", OCTOCAP_ROLE_NODE, 30) == OCTOCAP_OK);
}

// The identity's certificate re-signed by its CA with notAfter `days_from_now` days away (negative: in the past).
void resign_certificate(const std::string& keystore, const std::string& name, long days_from_now) {
  const std::string cert_path = keystore + "/" + name + "/cert.pem";
  FILE* f = std::fopen(cert_path.c_str(), "r");
  X509* cert = PEM_read_X509(f, nullptr, nullptr, nullptr);
  std::fclose(f);
  f = std::fopen((keystore + "/ca.key.pem").c_str(), "r");
  EVP_PKEY* ca_key = PEM_read_PrivateKey(f, nullptr, nullptr, nullptr);
  std::fclose(f);
  REQUIRE((cert && ca_key));
  X509_gmtime_adj(X509_getm_notBefore(cert), (days_from_now - 2) * 86400);
  X509_gmtime_adj(X509_getm_notAfter(cert), days_from_now * 86400);
  REQUIRE(X509_sign(cert, ca_key, EVP_sha256()) > 0);
  f = std::fopen(cert_path.c_str(), "w");
  PEM_write_X509(f, cert);
  std::fclose(f);
  X509_free(cert);
  EVP_PKEY_free(ca_key);
}

std::string check_error(const std::string& identity) {
  octocap_security_role_t role;
  if (octocap_keystore_check_identity(identity.c_str(), &role) == OCTOCAP_OK) return "";
  return octocap_last_error();
}

}  // namespace

TEST_CASE("keystore: a CA, signed governance and one identity per role, private keys owner-only", "[security]") {
  TempDir tmp;
  const std::string ks = tmp / "studio";
  make_studio(ks);
  CHECK(mode_of(ks) == 0700);
  CHECK(mode_of(ks + "/ca.key.pem") == 0600);
  CHECK(mode_of(ks + "/hub/key.pem") == 0600);
  CHECK(mode_of(ks + "/hub") == 0700);
  for (const auto& [name, role] : {std::pair<const char*, octocap_security_role_t>{"hub", OCTOCAP_ROLE_HUB},
                                   {"viewer", OCTOCAP_ROLE_VIEWER}, {"booth", OCTOCAP_ROLE_NODE}}) {
    octocap_security_role_t got = static_cast<octocap_security_role_t>(99);
    INFO(name << ": " << octocap_last_error());
    CHECK(octocap_keystore_check_identity((ks + "/" + name).c_str(), &got) == OCTOCAP_OK);
    CHECK(got == role);
  }
  // The governance admits nobody unauthenticated and encrypts everything; permissions name the certificate's subject.
  const std::string governance = text_of(ks + "/governance.xml");
  CHECK_THAT(governance, ContainsSubstring("<allow_unauthenticated_participants>false"));
  CHECK_THAT(governance, ContainsSubstring("<data_protection_kind>ENCRYPT"));
  const std::string viewer = text_of(ks + "/viewer/permissions.xml");
  CHECK_THAT(viewer, ContainsSubstring("<subject_name>CN=viewer,O=octocap</subject_name>"));
  CHECK_THAT(viewer, ContainsSubstring("<subscribe><topics><topic>*_definition</topic>"));
  CHECK_THAT(viewer, !ContainsSubstring("<publish>"));
  CHECK_THAT(text_of(ks + "/booth/permissions.xml"),
             ContainsSubstring("<publish><topics><topic>*_keypoints2d</topic></topics></publish>"));
  // A trailing slash names the same identity.
  CHECK(check_error(ks + "/hub/").empty());
}

TEST_CASE("keystore: what it refuses, each with its reason", "[security][misuse]") {
  TempDir tmp;
  const std::string ks = tmp / "studio";
  make_studio(ks);
  CHECK(octocap_keystore_create(ks.c_str(), 30) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("holds a keystore already"));
  CHECK(octocap_keystore_add_identity(ks.c_str(), "hub", OCTOCAP_ROLE_HUB, 30) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("exists already"));
  CHECK(octocap_keystore_add_identity(ks.c_str(), "../escape", OCTOCAP_ROLE_HUB, 30) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_keystore_add_identity(ks.c_str(), "", OCTOCAP_ROLE_HUB, 30) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_keystore_add_identity(ks.c_str(), "x", static_cast<octocap_security_role_t>(7), 30) ==
        OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_keystore_add_identity(ks.c_str(), "x", OCTOCAP_ROLE_HUB, 0) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_keystore_add_identity((tmp / "nothing").c_str(), "x", OCTOCAP_ROLE_HUB, 30) == OCTOCAP_ERROR_IO);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("ca.pem"));
  CHECK(octocap_keystore_create(nullptr, 30) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_keystore_check_identity(nullptr, nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_keystore_check_identity((ks + "/hub").c_str(), nullptr) == OCTOCAP_OK);
}

TEST_CASE("keystore: a broken identity is named with its cause before any participant starts", "[security][misuse]") {
  TempDir tmp;
  const std::string ks = tmp / "studio", foreign = tmp / "foreign";
  make_studio(ks);
  make_studio(foreign);
  CHECK_THAT(check_error(ks + "/nobody"), ContainsSubstring("no such identity folder"));
  fs::remove(ks + "/viewer/key.pem");
  CHECK_THAT(check_error(ks + "/viewer"), ContainsSubstring("viewer/key.pem: not found"));
  // Another keystore's certificate: not signed by this CA.
  fs::copy_file(foreign + "/hub/cert.pem", ks + "/hub/cert.pem", fs::copy_options::overwrite_existing);
  CHECK_THAT(check_error(ks + "/hub"), ContainsSubstring("not signed by the keystore's CA"));
  // A key that is not the certificate's.
  fs::copy_file(foreign + "/hub/cert.pem", foreign + "/booth/cert.pem", fs::copy_options::overwrite_existing);
  CHECK_THAT(check_error(foreign + "/booth"), ContainsSubstring("not the key of"));
  // Expired, and not yet valid, certificates (re-signed by the CA, so only the dates are wrong).
  resign_certificate(foreign, "viewer", -1);
  CHECK_THAT(check_error(foreign + "/viewer"), ContainsSubstring("expired on"));
  resign_certificate(foreign, "viewer", 10);  // valid from 8 days from now
  CHECK_THAT(check_error(foreign + "/viewer"), ContainsSubstring("not valid before"));
  // Permissions edited after signing: the signature no longer holds.
  std::string p7s = text_of(foreign + "/hub/permissions.p7s");
  p7s.replace(p7s.find("<publish>"), 9, "<subscribe>");
  std::ofstream(foreign + "/hub/permissions.p7s") << p7s;
  CHECK_THAT(check_error(foreign + "/hub"), ContainsSubstring("permissions.p7s: not signed by the keystore's CA"));
  // Garbage where a certificate belongs.
  std::ofstream(foreign + "/booth/cert.pem") << "not a certificate\n";
  CHECK_THAT(check_error(foreign + "/booth"), ContainsSubstring("not a PEM certificate"));
}

#ifdef OCTOCAP_HAVE_DDS
namespace {

// A capture node process (octocap detect --live) whose camera, dds://booth/cam01, is a real IP camera stream.
std::unique_ptr<testing::ChildProcess> node_process(const std::string& camera, uint32_t domain,
                                                    const std::string& topic, const std::string& identity) {
  std::vector<std::string> argv = {OCTOCAP_CLI_PATH, "detect", "--live", "--publish-keypoints", "--node", "booth",
                                   "--camera", camera, "--camera-name", "cam01", "--model", "movenet-lightning",
                                   "--detect-rate", "10", "--domain", std::to_string(domain), "--topic", topic,
                                   "--duration", "20", "--quiet"};
  if (!identity.empty()) argv.insert(argv.end(), {"--dds-security", identity});
  return std::make_unique<testing::ChildProcess>(argv);
}

}  // namespace

// One identity per process and domain: Cyclone's security plugins hold one configuration per domain in a process, so
// the hub is this process and each node is a process of its own, as on a studio network.
TEST_CASE("secured capture node: the keystore's node is heard by the hub; a foreign keystore's node and an unsecured "
          "one are not",
          "[security][dds][nodes][real][serial]") {
  TempDir tmp;
  const std::string ks = tmp / "studio", foreign = tmp / "foreign";
  make_studio(ks);
  make_studio(foreign);
  const uint32_t domain = testing::loopback_dds_domain();  // the children inherit the loopback configuration
  const std::string topic = "octocap_sec_" + std::to_string(getpid());
  const int port = testing::free_port_run(1);
  REQUIRE(port > 0);
  testing::ChildProcess camera({"/usr/bin/python3", std::string(OCTOCAP_SOURCE_DIR) + "/tests/support/rtsp_server.py",
                                "--port", std::to_string(port), "/cam=" + testing::kStreams + "cam01_960.h264"});
  REQUIRE(testing::port_accepts(port, 30000));
  const std::string url = "rtsp://127.0.0.1:" + std::to_string(port) + "/cam";
  auto receiver = std::make_shared<octocap::internal::KeypointReceiver>(domain, topic, ks + "/hub");
  octocap::internal::FeedOptions options;
  options.source.open_timeout_ms = 30000;  // the node loads its model and opens its video first
  octocap::internal::RemoteFeed feed(octocap::internal::parse_camera_spec("dds://booth/cam01"), options, receiver,
                                     [] {});
  for (const std::string& identity : {ks + "/booth", foreign + "/booth", std::string()}) {
    INFO("node identity '" << identity << "'");
    const uint64_t before = feed.status().grabbed;
    auto node = node_process(url, domain, topic, identity);
    if (identity == ks + "/booth") {
      feed.start();  // opening waits for the node's first keypoints
      CHECK(testing::wait_until([&] { return feed.status().grabbed >= before + 20; }, 30000));
    } else {
      // Long enough for its model, camera and discovery: the keystore's own node was heard within about 2 s.
      std::this_thread::sleep_for(std::chrono::seconds(6));
      CHECK(feed.status().grabbed == before);
    }
    node->kill_now();
    node->wait();
  }
  feed.stop();
  // A viewer's identity may not publish keypoints: the node stops at once, naming the topic and the role.
  const testing::Run wrong = testing::run_command(
      std::string(OCTOCAP_CLI_PATH) + " detect --live --publish-keypoints --camera " + url + " --model movenet-lightning --domain " + std::to_string(domain) + " --topic " + topic +
      " --duration 2 --quiet --dds-security " + ks + "/viewer 2>&1");
  INFO(wrong.output);
  CHECK(wrong.status != 0);
  CHECK_THAT(wrong.output, ContainsSubstring(topic + "_keypoints2d"));
  CHECK_THAT(wrong.output, ContainsSubstring("role viewer"));
}
#endif

TEST_CASE("secured configs through the C ABI: a bad identity fails the start, naming it; an unterminated path is refused",
          "[security][misuse]") {
  TempDir tmp;
  octocap_subscriber_config_t sub;
  octocap_subscriber_config_init(&sub);
  CHECK(sub.security[0] == '\0');  // plain DDS unless asked
  std::snprintf(sub.security, sizeof sub.security, "%s", (tmp / "nobody").c_str());
  octocap_subscriber_t* s = nullptr;
  const octocap_result_t r = octocap_subscriber_create(&sub, &s);
#ifdef OCTOCAP_HAVE_DDS
  CHECK(r == OCTOCAP_ERROR_IO);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("nobody: no such identity folder"));
#else
  CHECK(r == OCTOCAP_ERROR_UNSUPPORTED);
#endif
  CHECK(s == nullptr);
  std::memset(sub.security, 'A', sizeof sub.security);
  CHECK(octocap_subscriber_create(&sub, &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("cfg.security is not NUL-terminated"));

  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  CHECK(cfg.stream_security[0] == '\0');
  octocap_live_config_t live;
  octocap_live_config_init(&live);
  CHECK(live.remote_security[0] == '\0');
  octocap_node_config_t node;
  octocap_node_config_init(&node);
  CHECK(node.security[0] == '\0');
}
