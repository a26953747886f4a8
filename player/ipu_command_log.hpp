// ipu_commands.csv of a run directory (`vbim play --trace-detail ipu`; columns in docs/run-files.md):
// one row per IPU command the model issued, in issue order, with its command word as the EE writes
// it to IPU_CMD, its fields, the picture's IPU_CTRL, and its time on the simulated clock. Diffing it
// against an emulator's or a console's log: docs/porting.md, "Diffing the IPU commands".
#pragma once

#include <cstdint>
#include <string>

#include "ee/frame_buffers.hpp"
#include "ipu/ipu_unit.hpp"

namespace vbim::player {

std::string ipuCommandsHeader();
// The rows of one picture's commands: `stream` 0 the lightmap, 1 the sky; `variant` the picture's.
std::string ipuCommandLines(int stream, int variant, const ee::CompressedPicture& pic, const ipu::TimedPicture& tp);

}  // namespace vbim::player
