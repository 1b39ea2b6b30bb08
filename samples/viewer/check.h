// The viewer's one way to stop on a library error: an exception carrying the library's own message.
#pragma once
#include <stdexcept>
#include <string>

#include "octocap/octocap.h"

inline void check(octocap_result_t r, const std::string& what) {
  if (r != OCTOCAP_OK) throw std::runtime_error(what + ": " + octocap_last_error());
}
