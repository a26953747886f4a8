// Values a command takes beside a platform config, read the same way by every command (play,
// replay, profile, config): a simulated time with a unit, a catch-up policy's name, and a
// gs::GsError said against the config file that caused it. Each throws vbim::Error (bad input).
#pragma once

#include <string>

#include "gs/error.hpp"
#include "runtime/clock.hpp"

namespace vbim::config {

// A simulated time with a unit ("12.5s", "800ms"); vbim::Error naming the option `what` and `text`.
Tick parseTime(const std::string& what, const std::string& text);

// A `--policy` value checked against gs::kCatchupPolicies (vbim::Error naming the choices).
std::string catchupPolicy(const std::string& name);

// A GsError about the platform config, said the same way by every command: `FILE:LINE: key 'gs.x':
// message` for the first of its keys (by line) that the config file FILE sets; `FILE: message` when
// the file sets none of them; `the default platform config: message` without a file.
std::string gsConfigMessage(const gs::GsError& e, const std::string& configPath);

}  // namespace vbim::config
