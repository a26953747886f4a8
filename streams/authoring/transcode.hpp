// The same content at another quantiser or bitrate (`vbim profile --qscale/--bitrate`). Every picture
// of a VBIM stream is decoded (libavcodec, the authoring reference decoder) and re-authored through
// StreamWriter with the stream's own descriptor settings (game rate, loop frame, variants, container
// rate) and the new encoder settings, in memory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "streams/authoring/mpeg2_encoder.hpp"

namespace vbim::streams {

// Reads `path` (a VBIM stream) and returns it re-encoded with `encoder` (its containerFps is
// replaced by the stream's own). Throws AuthoringError naming the file when it is not a readable
// VBIM stream or a picture is missing or undecodable.
std::vector<std::uint8_t> transcodeStream(const std::filesystem::path& path, EncoderSettings encoder);
// The same for a stream already in memory (a file read off a disc image), named `name` in messages.
std::vector<std::uint8_t> transcodeStream(std::span<const std::uint8_t> stream, const std::string& name,
                                          EncoderSettings encoder);

}  // namespace vbim::streams
