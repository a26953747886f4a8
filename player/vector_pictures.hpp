// The pictures of a stream file the IPU and per-stage vectors are made from (player/known_answers.hpp).
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "player/known_answers.hpp"
#include "streams/descriptor.hpp"

namespace vbim::player {

// Every undamaged picture of a stream file by (stream id, global frame), and its descriptor.
struct StreamPictures {
  streams::Descriptor descriptor;
  std::map<std::pair<int, std::uint32_t>, std::vector<std::uint8_t>> pictures;
};

// Throws ConfigError naming the stream when it holds no descriptor or no picture.
StreamPictures picturesOf(const VectorStream& s);

}  // namespace vbim::player
