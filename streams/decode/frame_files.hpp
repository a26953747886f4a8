// Decoded frames as files, one per frame: frame_00000.png (RGBA, the GS alpha doubled so that 0x80
// is opaque), .exr (half-float RGBA, alpha 0x80 = 1.0), .yuv (the IPU's planar 4:2:0 output,
// Y then Cb then Cr) or .rgba (raw RGB32 as the IPU writes it: R, G, B, A bytes per pixel, rows top
// to bottom, alpha 0x80 = 1.0; what `vbim replay --frames` reads). The frame sink of decodeStream
// for `vbim decode`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "imageio/texel_files.hpp"
#include "ipu/csc.hpp"
#include "ipu/picture_decoder.hpp"
#include "runtime/image.hpp"

namespace vbim::streams {

enum class FrameFileFormat { Png, Exr, Yuv, Rgba };

// "png", "exr", "yuv", "rgba": the file name extension.
const char* extensionOf(FrameFileFormat format);
// "frame_00042.png": the file frame number `frame` is written as.
std::string frameFileName(int frame, FrameFileFormat format);

class FrameFileWriter {
 public:
  // `thresholds`: the SETTH thresholds of the RGB32 conversion (PNG, EXR and RGBA). `pngLevel`:
  // zlib's level for PNG files, 0 (stored) to 9 (imageio/png_encoder.hpp). `directory` is a staged
  // output directory (runs/output_dir.hpp): each file is written under its own name.
  FrameFileWriter(std::filesystem::path directory, FrameFileFormat format, ipu::CscThresholds thresholds = {},
                  int pngLevel = imageio::kDefaultTexelPngLevel);

  // Writes the frame the decoder holds as frame number `frame`. Throws Error (YUV, RGBA) or
  // imageio::ImageIoError (PNG, EXR) naming the file when it cannot be written.
  void write(int frame, const ipu::Decoder& decoder);

 private:
  std::filesystem::path directory_;
  FrameFileFormat format_;
  ipu::CscThresholds thresholds_;
  int pngLevel_;
  Rgba8Image rgba_;  // reused from frame to frame
  Yuv420Image yuv_;
  std::vector<float> floats_;
};

}  // namespace vbim::streams
