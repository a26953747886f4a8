// The IPU vectors: each chosen picture of the streams decoded (IDEC; a P or B picture's frame through
// its GOP, player/stream_frame_decoder.hpp) and converted (CSC) the ways a port can ask the IPU for,
// hashed in raster order and in the IPU's own macroblock order.
#include <cstdint>
#include <map>
#include <optional>
#include <span>

#include "ipu/csc.hpp"
#include "ipu/picture_decoder.hpp"
#include "player/frame_hash.hpp"
#include "player/known_answers.hpp"
#include "player/stream_frame_decoder.hpp"
#include "player/vector_pictures.hpp"

namespace vbim::player {

namespace {

// SETTH values of the threshold vectors: TH0 below which a pixel becomes transparent black, TH1
// below which its alpha becomes 0x40 (ipu/csc.hpp).
constexpr ipu::CscThresholds kThresholds{32, 96};

// Raster bytes (width x height pixels of `bpp` bytes) in the order the IPU writes them to the
// fromIPU FIFO: 16x16 macroblocks left to right, top to bottom, each 16 rows of 16 pixels.
std::vector<std::uint8_t> macroblockOrder(const std::vector<std::uint8_t>& raster, int width, int height, int bpp) {
  std::vector<std::uint8_t> out;
  out.reserve(raster.size());
  const std::size_t rowBytes = static_cast<std::size_t>(width) * bpp;
  for (int my = 0; my < height / 16; ++my) {
    for (int mx = 0; mx < width / 16; ++mx) {
      for (int y = 0; y < 16; ++y) {
        const std::size_t at =
            static_cast<std::size_t>(my * 16 + y) * rowBytes + static_cast<std::size_t>(mx) * 16 * bpp;
        out.insert(out.end(), raster.begin() + static_cast<std::ptrdiff_t>(at),
                   raster.begin() + static_cast<std::ptrdiff_t>(at + 16 * static_cast<std::size_t>(bpp)));
      }
    }
  }
  return out;
}

std::vector<std::uint8_t> rgb16Bytes(const std::vector<std::uint16_t>& px) {
  std::vector<std::uint8_t> out(px.size() * 2);
  for (std::size_t i = 0; i < px.size(); ++i) {
    out[2 * i] = static_cast<std::uint8_t>(px[i] & 0xFF);
    out[2 * i + 1] = static_cast<std::uint8_t>(px[i] >> 8);
  }
  return out;
}

// `frame`: the frame as the IPU holds it for display (a P or B picture's with its references).
void addPicture(std::string& t, const std::string& prefix, const std::vector<std::uint8_t>& data,
                const std::optional<StreamFrameDecoder::Frame>& frame) {
  const int w = frame ? frame->width : 0;
  const int h = frame ? frame->height : 0;
  t += prefix + "/picture bytes=" + std::to_string(data.size()) + ",size=" + std::to_string(w) + "x" +
       std::to_string(h) + "\n";
  if (w <= 0 || h <= 0 || w % 16 != 0 || h % 16 != 0) return;
  const auto both = [&](const std::string& name, const std::vector<std::uint8_t>& raster, int bpp) {
    const int hashWidth = w * bpp / 4;
    t += prefix + "/" + name + "/raster " + hashHex(hashAsImage(raster, hashWidth, h)) + "\n";
    t += prefix + "/" + name + "/macroblock " + hashHex(hashAsImage(macroblockOrder(raster, w, h, bpp), hashWidth, h)) +
         "\n";
  };
  for (const bool th : {false, true}) {
    const ipu::CscThresholds thresholds = th ? kThresholds : ipu::CscThresholds{};
    const std::string suffix = th ? "_th" : "";
    Rgba8Image rgba;
    ipu::convertToRgba32(frame->store, w, h, thresholds, rgba);
    both("rgb32" + suffix, rgba.pixels, 4);
    for (const bool dither : {false, true}) {
      std::vector<std::uint16_t> px;
      ipu::convertToRgb16(frame->store, w, h, thresholds, dither, px);
      both(std::string(dither ? "rgb16_dither" : "rgb16") + suffix, rgb16Bytes(px), 2);
    }
  }
}

}  // namespace

VectorFile ipuVectors(const std::vector<VectorStream>& streams, ipu::IdctKind idct) {
  std::string t =
      "# vbim known answers: the IPU's output per picture (ipu/picture_decoder.hpp, ipu/csc.hpp)\n"
      "# KEY ipu/STREAM/lightmap|sky/frame=GLOBAL_FRAME/picture  VALUE bytes=N,size=WxH: the picture as the\n"
      "#   EE hands it to the IPU (sequence header .. last slice) and its decoded size\n"
      "# KEY ipu/STREAM/lightmap|sky/frame=F/OUTPUT/raster|macroblock  VALUE the frame hash of the output:\n"
      "#   OUTPUT rgb32 (OFM 0), rgb16 (OFM 1, DTE 0), rgb16_dither (OFM 1, DTE 1); _th: SETTH TH0 = 32,\n"
      "#   TH1 = 96, else TH0 = TH1 = 0. raster: rows top to bottom; macroblock: the IPU's order, 16x16\n"
      "#   macroblocks left to right, top to bottom, each 16 rows of 16 pixels (64 qwords RGB32, 32 RGB16).\n"
      "#   The bytes are hashed as an RGBA8 image W x H (RGB32) or W/2 x H (RGB16, little-endian pixels).\n"
      "# IDCT: " +
      std::string(ipu::idctKindName(idct)) + " (platform parameter ipu.idct, docs/timing/ipu.md#idct)\n";
  bool noted = false;
  for (const VectorStream& s : streams) {
    const StreamPictures sp = picturesOf(s);
    const auto& pictures = sp.pictures;
    if (!sp.descriptor.intraOnly() && !noted) {
      t += "# " + s.label +
           " has P and B pictures: frame F's outputs are that frame as shown, decoded in decode order\n"
           "#   from the I picture opening its GOP (ee/decode_order.hpp); `picture` is frame F's own picture\n";
      noted = true;
    }
    for (const auto& [id, name] : {std::pair<int, const char*>{0xE0, "lightmap"}, {0xE1, "sky"}}) {
      const int index = sp.descriptor.streamIndex(static_cast<std::uint8_t>(id));
      if (index < 0) continue;
      ipu::DecoderOptions options;
      options.idct = idct;
      const int streamId = id;  // a structured binding cannot be captured before C++20's P1091 in clang 14
      StreamFrameDecoder decoded(sp.descriptor, index, options, [&](std::uint32_t g) -> std::span<const std::uint8_t> {
        const auto it = pictures.find({streamId, g});
        if (it == pictures.end()) return {};
        return it->second;
      });
      std::vector<std::uint32_t> frames;
      for (const auto& [key, data] : pictures) {
        if (key.first == id) frames.push_back(key.second);
      }
      if (frames.empty()) continue;
      // The first two pictures and the last: a port checks its extraction and its decode on each.
      std::vector<std::uint32_t> chosen{frames.front()};
      if (frames.size() > 1) chosen.push_back(frames[1]);
      if (frames.size() > 2) chosen.push_back(frames.back());
      for (const std::uint32_t f : chosen) {
        addPicture(t, "ipu/" + s.label + "/" + name + "/frame=" + std::to_string(f), pictures.at({id, f}),
                   decoded.frame(f));
      }
    }
  }
  return VectorFile{"ipu.txt", t};
}

}  // namespace vbim::player
