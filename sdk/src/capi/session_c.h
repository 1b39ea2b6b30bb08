// The C session config -> SessionConfig (shared by the session and the live handle).
#pragma once
#include "octocap/octocap.h"
#include "pipeline/session.h"

namespace octocap::capi {

// Any released struct size; the values are checked by Session itself.
SessionConfig session_config(const octocap_session_config_t* given);

}  // namespace octocap::capi
