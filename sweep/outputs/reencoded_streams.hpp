// `vbim profile --qscale/--bitrate`: the first disc's stream re-encoded at other settings
// (streams/authoring/transcode.hpp), held in memory, labelled `<stem>_q<Q>` and `<stem>_<K>kbps`.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sweep/profile_run.hpp"

namespace vbim::sweep {

// One stream per quantiser (1..31), then one per bitrate (1..9,800,000 bit/s), from `first` (read
// from `path`, whose stem labels them). Throws vbim::Error for a setting out of range and what
// the transcoder throws for a stream it cannot re-encode.
std::vector<std::shared_ptr<Stream>> reencodedStreams(const Stream& first, const std::string& path,
                                                      const std::vector<int>& qscales,
                                                      const std::vector<std::int64_t>& bitrates);

}  // namespace vbim::sweep
