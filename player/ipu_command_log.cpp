#include "player/ipu_command_log.hpp"

#include <cstdio>

namespace vbim::player {
namespace {

std::string hex32(std::uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08X", v);  // as PCSX2's IPU log prints IPU_CMD
  return buf;
}

const char* typeName(streams::PictureType t) {
  switch (t) {
    case streams::PictureType::I:
      return "I";
    case streams::PictureType::P:
      return "P";
    case streams::PictureType::B:
      return "B";
  }
  return "?";
}

}  // namespace

std::string ipuCommandsHeader() {
  return "stream,picture,frame,type,command,word,fields,ctrl,begin_tick,end_tick\n";
}

std::string ipuCommandLines(int stream, int variant, const ee::CompressedPicture& pic, const ipu::TimedPicture& tp) {
  std::string prefix = (stream == 0 ? "lightmap:" : "sky:") + std::to_string(variant) + "," +
                       std::to_string(pic.globalFrame) + "," + std::to_string(pic.seq) + "," + typeName(pic.type) + ",";
  const std::string ctrl = hex32(tp.ctrl);
  std::string out;
  for (const ipu::IssuedCommand& c : tp.issued) {
    out += prefix;
    out += ipu::opcodeName(ipu::opcodeOf(c.word));
    out += ',';
    out += hex32(c.word);
    out += ',';
    out += ipu::commandFields(c.word);
    out += ',';
    out += ctrl;
    out += ',';
    out += std::to_string(c.begin);
    out += ',';
    out += std::to_string(c.end);
    out += '\n';
  }
  return out;
}

}  // namespace vbim::player
