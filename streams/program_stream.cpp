#include "streams/program_stream.hpp"

#include <algorithm>
#include <string>

#include "streams/format.hpp"

namespace vbim::streams {

bool ProgramStreamReader::next(ParsedPack& pack) {
  while (!ended_ && pos_ < data_.size()) {
    packOffset_ = pos_;
    std::optional<StreamError> defect = parsePackAt(data_, pos_, pack);
    if (!defect) {
      pos_ += pack.size;
      ended_ = pack.hasEndCode;
      return true;
    }
    if (defect->kind == ErrorKind::Truncated) {
      ended_ = true;
    } else {
      // Resume after the defect: the bytes between are not trustworthy, a pack header is.
      pos_ = nextPackStart(std::max<std::size_t>(pos_, static_cast<std::size_t>(defect->byteOffset)) + 1);
      defect->message +=
          pos_ < data_.size() ? "; skipping to the next pack at byte " + std::to_string(pos_) : "; no pack follows";
    }
    defects_.push_back(std::move(*defect));
    if (!pack.packets.empty()) return true;
  }
  return false;
}

std::size_t ProgramStreamReader::nextPackStart(std::size_t from) const {
  for (std::size_t i = from; i + 3 < data_.size(); ++i)
    if (data_[i] == 0 && data_[i + 1] == 0 && data_[i + 2] == 1 && data_[i + 3] == kPackStartCode) return i;
  return data_.size();
}

}  // namespace vbim::streams
