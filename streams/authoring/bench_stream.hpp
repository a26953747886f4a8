// The content of the player's speed bench and memory test (issue #7 items 8 and 9; kept here so the
// tests build without the benchmarks), authored in memory once: a 512x512 lightmap and a 256x128 sky per frame, 2 s of
// game time per stream frame, played at 59.94 Hz (NTSC). The GS config must upload in strips to fit VRAM
// (gs.upload_mode = "strips", gs.sky_height = 128). Two generators: the synthetic day
// (streams/authoring/synthetic_day.hpp, smooth, like real lightmaps) and noise (every macroblock busy: the largest
// pictures the VBV allows, for tests that need a big file quickly).
#pragma once

#include <cstdint>
#include <vector>

namespace vbim::streams {

enum class BenchContent { SyntheticDay, Noise };

// A finished VBIM stream (2048-byte packs) of `frames` frames. stretchContainerTime = false makes a
// stream whose lightmap and sky drift apart in the file when the frames are large (noise).
std::vector<std::uint8_t> authorBenchStream(int frames, BenchContent content, int qscale = 3,
                                            bool stretchContainerTime = true);

}  // namespace vbim::streams
