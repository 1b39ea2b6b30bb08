// The C session config -> SessionConfig (shared by the session and the live handle).
#pragma once
#include "octocap/octocap.h"
#include "pipeline/session.h"

namespace octocap::internal::capi {

// Any released struct size; the values are checked by Session itself.
SessionConfig session_config(const octocap_session_config_t* given);
octocap_session_config_t c_session_config(const SessionConfig& s);

}  // namespace octocap::internal::capi
