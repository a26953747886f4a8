// The same content at another quantiser, bitrate or GOP structure (`vbim profile --qscale/--bitrate`,
// a sweep plan's `qscales`, `bitrates` and `gops`). Every picture
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
// VBIM stream or a picture is missing or undecodable. `sources`, when given, receives the lightmap
// frames as the encoder takes them (each decoded picture converted by rgbaToYuv420), in frame order
// over all variants: what a re-encode's quality is measured against.
std::vector<std::uint8_t> transcodeStream(const std::filesystem::path& path, EncoderSettings encoder,
                                          std::vector<Yuv420Image>* sources = nullptr);
// The same for a stream already in memory (a file read off a disc image), named `name` in messages.
std::vector<std::uint8_t> transcodeStream(std::span<const std::uint8_t> stream, const std::string& name,
                                          EncoderSettings encoder, std::vector<Yuv420Image>* sources = nullptr);

}  // namespace vbim::streams
