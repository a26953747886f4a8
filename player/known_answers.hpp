// Known-answer vectors a console port can reproduce, independent of every timing constant
// (docs/porting.md, "Known-answer vectors"): the IPU's output per picture of the sample streams, in
// raster and macroblock order; GS blend steps; sceCdStRead result sequences for scripted ring
// scenarios; the frame hash itself. `vbim vectors --out DIR` writes them, `vbim vectors --check DIR`
// compares a port's captured files against them.
//
// Every file is text: lines starting with '#' are comments, every other line is `KEY VALUE`
// (one space; the key names the input, the value is the answer). Keys are unique within a file.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ipu/kernels.hpp"
#include "runtime/image.hpp"

namespace vbim::player {

struct VectorFile {
  std::string name;  // file name, e.g. "blend.txt"
  std::string text;
};

// A stream file whose pictures become IPU vectors: `label` names it in the keys (e.g. "day_clear").
struct VectorStream {
  std::string label;
  std::span<const std::uint8_t> bytes;
};

// The files, in a fixed order: frame_hash.txt, blend.txt, cdstread.txt, ipu.txt, then the per-stage
// vlc.txt, idct.txt, csc.txt and draw.txt. `idct` is the platform's inverse DCT (ipu.idct): the IPU,
// IDCT and CSC vectors depend on it.
std::vector<VectorFile> knownAnswerVectors(const std::vector<VectorStream>& streams,
                                           ipu::IdctKind idct = ipu::kDefaultIdct);

VectorFile frameHashVectors();
VectorFile blendVectors();
VectorFile streamReadVectors();
// Throws ConfigError when a stream holds no descriptor or no picture.
VectorFile ipuVectors(const std::vector<VectorStream>& streams, ipu::IdctKind idct = ipu::kDefaultIdct);

// The per-stage vectors (player/known_answers_stages.cpp): chosen blocks of the streams' intra
// pictures through VLC, IDCT and CSC, and the blend draw by draw. Throw ConfigError when a stream
// holds no picture or the block walk disagrees with the decoder.
VectorFile vlcVectors(const std::vector<VectorStream>& streams);
VectorFile idctVectors(const std::vector<VectorStream>& streams, ipu::IdctKind idct = ipu::kDefaultIdct);
VectorFile cscVectors(const std::vector<VectorStream>& streams, ipu::IdctKind idct = ipu::kDefaultIdct);
VectorFile drawVectors();

// The stage a vector file holds: its name without ".txt" (e.g. "vlc").
std::string vectorStage(const VectorFile& f);

// The frame hash (player/frame_hash.hpp) of `bytes` read as an RGBA8 image `width` pixels (4 bytes
// each) wide: how the vectors hash any IPU output (RGB16 output is read as 2 pixels per 4 bytes).
std::uint64_t hashAsImage(std::span<const std::uint8_t> bytes, int width, int height);

// The image of the frame-hash vectors: byte i is (i * 131 + seed * 7 + (i >> 8)) & 0xFF.
Rgba8Image patternImage(int width, int height, int seed);

struct VectorDifference {
  std::string file;
  std::string entry;  // the key, or the line number of a malformed line
  std::string expected;
  std::string found;  // "(missing)" when the port's file lacks the entry
  // Where in a value of many elements the two first differ, with both elements: "element 17 of 64"
  // (comma- or space-separated lists), "byte 130 of 1024" (hex strings longer than a hash); empty
  // otherwise.
  std::string place;
  std::string expectedElement;
  std::string foundElement;
};
// Fills a difference's place and elements from its two values (valueDifferencePlace below).
void locateDifference(VectorDifference& d);

// The first difference between an expected vector file and a port's (`found` is null when the
// port's directory has no such file). Entries are compared in the expected file's order; a key the
// expected file does not have is a difference too.
std::optional<VectorDifference> compareVectors(const VectorFile& expected, const std::string* found);

// How much of one vector file a port reproduces, for a partial bring-up (docs/porting.md): every
// selected entry compared, not only the first.
struct VectorScore {
  std::string file;
  bool found = true;                          // the port's directory has the file
  std::size_t checked = 0;                    // expected entries selected
  std::size_t matched = 0;                    // ... equal in the port's file
  std::size_t differ = 0;                     // ... with another value
  std::size_t missing = 0;                    // ... absent (all of them when the file is)
  std::size_t extra = 0;                      // selected keys the expected file does not have
  std::vector<VectorDifference> differences;  // in the expected file's order, then the extra keys
  bool passed() const { return matched == checked && extra == 0; }
};
// `only`: shell patterns (fnmatch: `*` any run of characters, `/` included, `?` one, `[...]` a set)
// a key must match to be selected; empty selects every entry.
VectorScore scoreVectors(const VectorFile& expected, const std::string* found,
                         const std::vector<std::string>& only = {});
// True when `key` matches one of `only` (or `only` is empty).
bool vectorKeySelected(const std::string& key, const std::vector<std::string>& only);

}  // namespace vbim::player
