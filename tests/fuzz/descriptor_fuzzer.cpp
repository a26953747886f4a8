// libFuzzer target: the playback descriptor's body reader on any bytes. A body it accepts must
// serialise and read back to the same descriptor.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "streams/descriptor.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const vbim::streams::DescriptorParse p = vbim::streams::parseDescriptor(std::span<const std::uint8_t>(data, size));
  if (!p.descriptor) return 0;
  const std::vector<std::uint8_t> again = vbim::streams::serialize(*p.descriptor);
  const vbim::streams::DescriptorParse q = vbim::streams::parseDescriptor(again);
  if (!q.descriptor) std::abort();  // what was read must be writable and readable again
  return 0;
}
