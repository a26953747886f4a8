// Paths of the committed sample streams for the player tests (ctest sets VBIM_SOURCE_DIR).
#pragma once

#include <cstdlib>
#include <string>

namespace vbim::player::testing {

inline std::string sourceDir() {
  const char* d = std::getenv("VBIM_SOURCE_DIR");
#ifdef VBIM_SOURCE_DIR_DEFAULT
  return d != nullptr ? d : VBIM_SOURCE_DIR_DEFAULT;
#else
  return d != nullptr ? d : ".";
#endif
}
inline std::string samplePath(const std::string& name) {
  return sourceDir() + "/streams/samples/" + name;
}

}  // namespace vbim::player::testing
