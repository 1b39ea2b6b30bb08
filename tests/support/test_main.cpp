// The test runner's main: Catch's own, with every test case tagged by its file ([#test_rig] for rig/test_rig.cpp,
// as -# would), so that tests/CMakeLists.txt finds a folder's tests by its files' names and labels them.
#include <catch2/catch_session.hpp>

int main(int argc, char* argv[]) {
  Catch::Session session;
  if (const int rc = session.applyCommandLine(argc, argv); rc != 0) return rc;
  session.configData().filenamesAsTags = true;
  return session.run();
}
