// The lighting generator's pictures (lighting/): heightfields, colour and cloud maps in; lightmaps,
// sky domes and debug layers out, read and written through imageio/. A target of its own
// (vbim_lighting_files), so the generator itself (vbim_lighting) needs the standard library only.
//
// Errors: imageio::ImageIoError for the file (unreadable, wrong channel count); LightingError for what it
// holds (a NaN height, lighting/terrain.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "lighting/float_image.hpp"
#include "lighting/terrain.hpp"

namespace vbim::lighting {

// A single-channel heightfield. Integer samples are kept exact (full scale = `verticalScale`
// metres, so a 16-bit count is verticalScale / 65535 m); float samples are metres / verticalScale.
Terrain readHeightfield(const std::string& path, double cellSize, double verticalScale);

// True when the heightfield's samples are floating point (heights), false for integer counts.
bool heightfieldHasFloatSamples(const std::string& path);

// An RGB colour (albedo) map, linear. 8/16-bit files are taken as sRGB-encoded and linearised,
// float files as linear. One channel is grey; a fourth channel (alpha) is ignored.
FloatImage readColourMap(const std::string& path);

// A single-channel image with values 0..1 (cloud density); values outside are clamped.
FloatImage readDensityMap(const std::string& path);

// By extension: .exr as 32-bit floats (exact), anything else (.png, .tif) as 8-bit linear,
// round(255 * value) clamped to [0, 1].
void writeImage(const std::filesystem::path& path, const FloatImage& image);

}  // namespace vbim::lighting
