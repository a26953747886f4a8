// The recipe of the committed sample stream streams/samples/day_clear.vbim (streams/samples/README.md):
// the procedural terrain, 256x256 texels of 20 m, lit over a day from 0 h to 24 h in 24 frames
// with a 128x64 sky dome, -1 EV, quantiser 6, one frame per game second, variant "clear". What
// `vbim author --procedural --size 256 --cell-size 20 --sky-width 128 --exposure -1 --q 6
// --frame-count 24 --start-hour 0 --end-hour 24 --fps 1` authors, as settings: `vbim demo` authors
// its stream with them, and a test checks the result equals the sample byte for byte.
#pragma once

#include "lighting/authoring/technique_a_stream.hpp"

namespace vbim::lighting {

// About two seconds of host time with 2 threads (the output does not depend on `threads`).
TechniqueAStreamSettings sampleDaySettings(unsigned threads = 2);

}  // namespace vbim::lighting
