// Re-encoded streams (streams/authoring/transcode.hpp, FFmpeg), in a library of their own so that a
// program without FFmpeg (`vbim`) can run every sweep that re-encodes nothing:
// `vbim profile --qscale/--bitrate`'s, the first disc's stream re-encoded at other settings, held in
// memory, labelled `<stem>_q<Q>` and `<stem>_<K>kbps`; and a sweep plan's re-encoded streams.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "runtime/image.hpp"
#include "sweep/plan.hpp"
#include "sweep/profile_run.hpp"

namespace vbim::sweep {

// One stream per quantiser (1..31), then one per bitrate (1..9,800,000 bit/s), from `first` (read
// from `path`, whose stem labels them). Throws vbim::Error for a setting out of range and what
// the transcoder throws for a stream it cannot re-encode.
std::vector<std::shared_ptr<Stream>> reencodedStreams(const Stream& first, const std::string& path,
                                                      const std::vector<int>& qscales,
                                                      const std::vector<std::int64_t>& bitrates);

// A sweep plan's re-encoded stream (sweep/outputs/study.hpp's StreamTranscoder): the file of `s` at
// its quantiser or bitrate and GOP structure; `sources`, when given, receives the frames encoded.
std::vector<std::uint8_t> transcodePlanStream(const StreamSpec& s, std::vector<Yuv420Image>* sources);

}  // namespace vbim::sweep
