#include "streams/decode/decode_input.hpp"

#include <fstream>
#include <iterator>
#include <stdexcept>

#include "runtime/error.hpp"
#include "streams/disc/stream_disc.hpp"

namespace vbim::streams {

DecodeInput readDecodeInput(const std::string& input, const std::string& file) {
  DecodeInput in{{}, input, {}};
  if (isIsoImage(input) || !file.empty()) {
    const StreamDisc disc = openStreamDisc(input, file);
    in.bytes = readDiscFile(*disc.disc, disc.file);
    in.name += " " + disc.file.path;
    in.fileOnDisc = disc.file.path;
    return in;
  }
  std::ifstream f(input, std::ios::binary);
  if (!f) throw Error(input + ": cannot open the file");
  in.bytes.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  return in;
}

std::uint8_t parseStreamId(const std::string& text) {
  std::size_t used = 0;
  unsigned long id = 0x100;
  try {
    id = std::stoul(text, &used, 0);
  } catch (const std::logic_error&) {
  }
  if (used != text.size() || id > 0xFF)
    throw Error("--stream-id " + text + ": expected a PES stream id such as 0xE1 (video: 0xE0..0xEF)");
  return static_cast<std::uint8_t>(id);
}

FrameFileFormat frameFileFormatNamed(const std::string& name) {
  if (name == "exr") return FrameFileFormat::Exr;
  if (name == "yuv") return FrameFileFormat::Yuv;
  if (name == "rgba") return FrameFileFormat::Rgba;
  return FrameFileFormat::Png;
}

}  // namespace vbim::streams
