// Image files for the lighting generator, through OpenImageIO (any format it reads: 16-bit PNG,
// TIFF, EXR, ...). Kept out of vbim_lighting so the generator itself needs the standard library only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lighting/float_image.hpp"
#include "lighting/terrain.hpp"
#include "runtime/image.hpp"

namespace vbim::lighting {

// A single-channel heightfield. Integer samples are kept exact (full scale = `verticalScale`
// metres, so a 16-bit count is verticalScale / 65535 m); float samples are metres / verticalScale.
// Fails (LightingError naming the file) when the file cannot be read, is not single-channel, is
// empty or holds NaN or infinite heights.
Terrain readHeightfield(const std::string& path, double cellSize, double verticalScale);

// An RGB colour (albedo) map, linear. 8/16-bit files are taken as sRGB-encoded and linearised,
// float files as linear. One channel is grey; a fourth channel (alpha) is ignored.
FloatImage readColourMap(const std::string& path);

// A single-channel image with values 0..1 (cloud density).
FloatImage readDensityMap(const std::string& path);

// Writes by extension: .exr as 32-bit float (1 or 3 channels), .png / .tif as 8-bit linear,
// clamped to [0, 1]. Written under a temporary name and renamed when complete.
void writeImage(const std::string& path, const FloatImage& image);

// 16-bit single-channel PNG / TIFF (horizon codes, exactly as stored).
void writeGray16(const std::string& path, int width, int height, const std::vector<std::uint16_t>& pixels);

}  // namespace vbim::lighting
