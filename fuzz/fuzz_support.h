// What every fuzz target shares: the input written to a file (the readers take paths), and the rule that an
// octocap::internal::Error (a clear refusal) is a correct answer while anything else escaping is a finding.
#pragma once
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

namespace fuzz {

// A per-process scratch file with the given extension, rewritten for each input.
inline std::string write_input(const uint8_t* data, size_t size, const std::string& extension) {
  const std::string path = "/tmp/octocap-fuzz-" + std::to_string(getpid()) + extension;
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) __builtin_trap();
  if (size) std::fwrite(data, 1, size, f);
  std::fclose(f);
  return path;
}

}  // namespace fuzz
