#include "streams/stream_error.hpp"

namespace vbim::streams {

const char* toString(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::ShortSector:
      return "short sector";
    case ErrorKind::BadPackHeader:
      return "bad pack header";
    case ErrorKind::BadPes:
      return "bad PES packet";
    case ErrorKind::PackOverrun:
      return "pack overrun";
    case ErrorKind::PictureDropped:
      return "picture dropped";
    case ErrorKind::PictureMismatch:
      return "picture mismatch";
    case ErrorKind::BadDescriptor:
      return "bad descriptor";
    case ErrorKind::Truncated:
      return "truncated";
  }
  return "unknown";
}

std::string StreamError::describe() const {
  return "sector " + std::to_string(sector) + " (byte " + std::to_string(byteOffset) + "): " + toString(kind) + ": " +
         message;
}

}  // namespace vbim::streams
