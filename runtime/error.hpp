// The errors of vbim. Every exception the project throws on purpose is a vbim::Error; a folder has
// a type of its own only where a caller tells its errors apart (iop::DiscError,
// streams::StreamProbeError, gs::GsError, streams::AuthoringError, lighting::LightingError, ...;
// docs/architecture.md, "Names"), so a caller can catch one folder's problems or all of them.
// what() names the input (file, key, byte, sector), the place and what was expected, so a command
// prints it as it is.
#pragma once

#include <stdexcept>

namespace vbim {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The kernel's error: a parameter, platform config or fault plan that is invalid (a value out of
// range, an unknown key, parameters that contradict each other, a malformed fault). Thrown by the
// parameter checks of the model and by config/ while it reads TOML; names the file, line and key.
class ConfigError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim
