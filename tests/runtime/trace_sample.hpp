// A small trace with two tracks and a counter, shared by the trace tests of the model
// (trace_test.cpp) and the one that parses its JSON with a JSON library (trace_json_test.cpp).
#pragma once

#include "runtime/trace.hpp"

namespace vbim::testing {

inline Tracer sampleTrace() {
  Tracer t;
  const auto drive = t.track("drive");
  const auto ipu = t.track("ipu");
  const auto ring = t.counter("ring.banks");
  t.span(drive, 0, fromMs(2), "read");
  t.begin(ipu, fromUs(500), "decode");
  t.end(ipu, fromUs(1500));
  t.value(ring, 0, 0);
  t.value(ring, fromMs(2), 1);
  t.value(ring, fromMs(3), 1);  // repeated value: dropped
  t.instant(drive, fromMs(5), "stall");
  return t;
}

}  // namespace vbim::testing
