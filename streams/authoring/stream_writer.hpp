// Authoring API: frames in, one finished VBIM stream out. Takes frames one at a time from memory, so
// a content generator (Technique A) can feed it without image files:
//
//   StreamWriter w(settings);
//   w.beginVariant("clear");
//   for (...) w.addFrame(lightmap, &sky);
//   w.beginVariant("overcast");  ...
//   writeStreamFile("day.vbim", w.finish());
//
// Each frame is converted to YCbCr 4:2:0, encoded as an MPEG-2 picture (stream 0xE0 lightmap, 0xE1
// sky): intra by default, or in GOPs with P and B pictures (EncoderSettings::gop, bFrames), where every
// variant's first frame and its loop frame are I pictures that start a GOP; finish() muxes them into 2048-byte packs,
// frames spaced in container time so the two streams stay in step (containerStretch()). Variants follow one another on
// one timeline. finish() reads the muxed stream back with the Demuxer to build the descriptor index and puts the
// descriptor packs in front. The whole stream is held in memory until then (about 40 KiB per frame pair at 720x576).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "runtime/image.hpp"
#include "streams/authoring/mpeg2_encoder.hpp"
#include "streams/descriptor.hpp"

namespace vbim::streams {

struct AuthorSettings {
  Rational gameFps{1, 1};       // stream frames per second of game time (descriptor)
  std::uint32_t loopFrame = 0;  // frame playback returns to after the last one
  EncoderSettings encoder;      // quantiser or bitrate, container frame rate
  bool withSky = true;          // every frame has a sky picture (stream 0xE1)
  // Space large frames out in container time so the muxer keeps the streams in step (see
  // containerStretch()); false keeps the container frame rate exact and lets them drift.
  bool stretchContainerTime = true;
};

// Largest frame side: MPEG-2 horizontal/vertical_size without extension bits is 12 bits.
inline constexpr int kMaxFrameSide = 4080;

class StreamWriter {
 public:
  explicit StreamWriter(AuthorSettings s);
  ~StreamWriter();
  StreamWriter(const StreamWriter&) = delete;
  StreamWriter& operator=(const StreamWriter&) = delete;

  // Starts a variant (weather). Every variant must have as many frames as the first one.
  void beginVariant(const std::string& name);
  // Adds the next frame of the current variant (the first call starts a variant "default" if none
  // was begun). `sky` must be given exactly when settings.withSky. Throws AuthoringError for a frame
  // of the wrong size (not a multiple of 16, or unlike the first frame of its stream).
  void addFrame(const Rgba8Image& lightmap, const Rgba8Image* sky = nullptr);
  // Completes the stream and returns its bytes (a whole number of 2048-byte packs).
  std::vector<std::uint8_t> finish();

  std::uint32_t framesInCurrentVariant() const { return framesInVariant_; }
  const Descriptor& descriptor() const { return descriptor_; }
  // Largest quantiser the encoders used (above the requested one if the VBV forced re-quantising).
  int maxQscaleUsed() const;
  // After finish(): how many container frame periods apart the frames were placed (1 unless the
  // largest frame would not fit one period at the DVD mux rate; see stream_writer.cpp). The
  // descriptor's ptsPerFrame includes it.
  std::uint32_t containerStretch() const { return stretch_; }

 private:
  struct Encoders;
  void checkSize(const Rgba8Image& img, const char* what, int& w, int& h) const;
  void open();
  void closeVariant();
  void send(const Rgba8Image& lightmap, const Rgba8Image* sky, std::int64_t pts, Mpeg2Encoder::Force force);
  void sendHeld(bool beforeIntra);

  AuthorSettings settings_;
  std::unique_ptr<Encoders> enc_;
  Descriptor descriptor_;
  std::uint32_t framesInVariant_ = 0;
  std::uint32_t framesTotal_ = 0;
  int lmW_ = 0, lmH_ = 0, skyW_ = 0, skyH_ = 0;
  bool finished_ = false;
  std::uint32_t stretch_ = 1;
  // With B pictures the frame before a forced I picture (the next variant's first, the loop frame)
  // must be forced to a reference, which is known only when the next frame comes: each frame waits here
  // for the next one.
  struct Held {
    Rgba8Image lightmap;
    std::optional<Rgba8Image> sky;
    std::int64_t pts = 0;
    Mpeg2Encoder::Force force = Mpeg2Encoder::Force::None;
  };
  std::optional<Held> held_;
};

// Drops libav's own messages below errors for the rest of the process (the authoring functions call
// it: their errors are thrown, libav's warnings are noise to a user).
void quietLibavLog();

// Writes `bytes` to `path` under a temporary name in the same directory and renames it into place,
// so `path` holds a complete stream or is left as it was. Throws AuthoringError naming the file.
void writeStreamFile(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

}  // namespace vbim::streams
