// The message of the DiscError a call throws, or "" when it throws none: the disc and ISO tests
// compare messages, not only that something was thrown.
#pragma once

#include <string>

#include "iop/error.hpp"

namespace vbim::iop::test {

std::string discErrorOf(auto&& f) {
  try {
    f();
  } catch (const DiscError& e) {
    return e.what();
  }
  return "";
}

}  // namespace vbim::iop::test
