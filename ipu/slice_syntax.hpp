// Syntax both slice decoders read the same way (ISO/IEC 13818-2 §6.2.4-6.2.5; 11172-2 §2.4.2.6-7):
// the slice header, macroblock_address_increment with escapes and stuffing, the escaped DCT level,
// and the per-macroblock bit record for the timing model.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ipu/bit_reader.hpp"
#include "ipu/decode_report.hpp"
#include "ipu/slice_decoder.hpp"
#include "ipu/vlc_tables.hpp"

namespace vbim::ipu {

// After the slice start code: the macroblock row, quantiser_scale_code and the skipped extra
// information. ok = false with `why` set when the header is cut short or the scale code is 0.
struct SliceHeader {
  int row = 0;
  int quantiserScaleCode = 0;
  bool ok = false;
  IssueKind why = IssueKind::kBadHeader;
};

inline SliceHeader readSliceHeader(BitReader& br, const PictureParams& pp, int code) {
  SliceHeader h;
  h.row = code - 1;
  if (pp.tallPicture && !pp.mpeg1) h.row += static_cast<int>(br.read(3)) << 7;
  if (h.row >= pp.mbRows) {
    h.why = IssueKind::kBadSlicePosition;
    return h;
  }
  h.quantiserScaleCode = static_cast<int>(br.read(5));
  if (!pp.mpeg1 && br.peek(1)) br.skip(9);  // intra_slice_flag, intra_slice, reserved_bits
  while (br.readBit()) {                    // extra_bit_slice / extra_information_slice
    br.skip(8);
    if (br.overrun()) break;
  }
  h.ok = !br.overrun() && h.quantiserScaleCode != 0;
  h.why = br.overrun() ? IssueKind::kTruncatedSlice : IssueKind::kBadHeader;
  return h;
}

// macroblock_address_increment (B.1) with macroblock_escape (+33) and MPEG-1 stuffing. False on an
// invalid code or past the end (escapes and stuffing are 11 bits each, so this ends).
inline bool readAddressIncrement(BitReader& br, const VlcTables& t, int& inc) {
  inc = 0;
  for (;;) {
    const VlcEntry e = t.mbAddressIncrement[br.peek(11)];
    if (e.len == 0 || br.overrun()) return false;
    br.skip(e.len);
    if (e.value == kMbaEscape) {
      inc += 33;
    } else if (e.value != kMbaStuffing) {
      inc += e.value;
      return true;
    }
  }
}

// The run and level after a DCT escape code (6 bits): 12-bit signed level, or MPEG-1's 8 or 16
// bits (11172-2 §2.4.3.7).
template <bool Mpeg1>
inline int readEscapeLevel(BitReader& br, int& run) {
  br.skip(6);
  run = static_cast<int>(br.read(6));
  if (!Mpeg1) return br.readSigned(12);
  int level = br.readSigned(8);
  if (level == 0) {
    level = static_cast<int>(br.read(8));
  } else if (level == -128) {
    level = static_cast<int>(br.read(8)) - 256;
  }
  return level;
}

// Records where a decoded macroblock's bits ended (MacroblockBits) and starts the next one.
inline void recordMacroblock(std::vector<MacroblockBits>* trace, int address, std::size_t pos, std::size_t& mbStart,
                             std::size_t offset) {
  if (trace) {
    trace->push_back(MacroblockBits{static_cast<std::uint32_t>(address), static_cast<std::uint32_t>(pos - mbStart),
                                    static_cast<std::uint32_t>(offset + (pos + 7) / 8), mbStart == 0});
  }
  mbStart = pos;
}

}  // namespace vbim::ipu
