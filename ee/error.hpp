// The EE's probe throws streams::StreamProbeError (streams/descriptor_probe.hpp), the reader's own
// check, moved down there so that the disc-image tools need no EE. Only cli/cmd_config.cpp still
// includes this header (without using it); it goes when that file stops (issue #32).
#pragma once

#include "streams/descriptor_probe.hpp"
