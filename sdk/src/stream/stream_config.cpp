#include "stream/stream_config.h"

#include <cctype>

#include "core/error.h"

namespace octocap::internal {

void check_dds_names(uint32_t domain_id, const std::string& topic, const std::string& what) {
  if (domain_id > 232) throw Error(Errc::invalid_argument, what + " DDS domain id must be 0..232");
  if (topic.empty()) throw Error(Errc::invalid_argument, what + " topic must not be empty");
  for (char c : topic)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
      throw Error(Errc::invalid_argument, what + " topic may hold letters, digits and '_' only");
}

void StreamConfig::validate() const {
  check_dds_names(domain_id, topic, "stream");
  if (history_depth < 1 || history_depth > 100000)
    throw Error(Errc::invalid_argument, "stream history depth must be 1..100000");
}

}  // namespace octocap::internal
