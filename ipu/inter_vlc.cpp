#include "ipu/inter_vlc.hpp"

#include <cstddef>

namespace vbim::ipu {
namespace {

struct Code {
  std::uint8_t len;
  std::uint16_t code;
  std::uint8_t value;
};

constexpr std::uint8_t kQ = kMbQuant;
constexpr std::uint8_t kF = kMbForward;
constexpr std::uint8_t kB = kMbBackward;
constexpr std::uint8_t kP = kMbPattern;
constexpr std::uint8_t kI = kMbIntra;

// Table B.3 macroblock_type in P pictures.
constexpr Code kB3[] = {
    {1, 0x1, kF | kP},      {2, 0x1, kP},      {3, 0x1, kF},      {5, 0x3, kI},
    {5, 0x2, kQ | kF | kP}, {5, 0x1, kQ | kP}, {6, 0x1, kQ | kI},
};

// Table B.4 macroblock_type in B pictures.
constexpr Code kB4[] = {
    {2, 0x2, kF | kB},      {2, 0x3, kF | kB | kP}, {3, 0x2, kB},      {3, 0x3, kB | kP},
    {4, 0x2, kF},           {4, 0x3, kF | kP},      {5, 0x3, kI},      {5, 0x2, kQ | kF | kB | kP},
    {6, 0x3, kQ | kF | kP}, {6, 0x2, kQ | kB | kP}, {6, 0x1, kQ | kI},
};

// Table B.9 coded_block_pattern (4:2:0): the pattern, bit 5 for block 0 (Y top left) .. bit 0 for
// block 5 (Cr). The 9-bit code for 0 is MPEG-2 only (11172-2 has no such code; it never appears).
constexpr Code kB9[] = {
    {3, 0x7, 60},  {4, 0xD, 4},   {4, 0xC, 8},   {4, 0xB, 16},  {4, 0xA, 32},  {5, 0x13, 12}, {5, 0x12, 48},
    {5, 0x11, 20}, {5, 0x10, 40}, {5, 0xF, 28},  {5, 0xE, 44},  {5, 0xD, 52},  {5, 0xC, 56},  {5, 0xB, 1},
    {5, 0xA, 61},  {5, 0x9, 2},   {5, 0x8, 62},  {6, 0xF, 24},  {6, 0xE, 36},  {6, 0xD, 3},   {6, 0xC, 63},
    {7, 0x17, 5},  {7, 0x16, 9},  {7, 0x15, 17}, {7, 0x14, 33}, {7, 0x13, 6},  {7, 0x12, 10}, {7, 0x11, 18},
    {7, 0x10, 34}, {8, 0x1F, 7},  {8, 0x1E, 11}, {8, 0x1D, 19}, {8, 0x1C, 35}, {8, 0x1B, 13}, {8, 0x1A, 49},
    {8, 0x19, 21}, {8, 0x18, 41}, {8, 0x17, 14}, {8, 0x16, 50}, {8, 0x15, 22}, {8, 0x14, 42}, {8, 0x13, 15},
    {8, 0x12, 51}, {8, 0x11, 23}, {8, 0x10, 43}, {8, 0xF, 25},  {8, 0xE, 37},  {8, 0xD, 26},  {8, 0xC, 38},
    {8, 0xB, 29},  {8, 0xA, 45},  {8, 0x9, 53},  {8, 0x8, 57},  {8, 0x7, 30},  {8, 0x6, 46},  {8, 0x5, 54},
    {8, 0x4, 58},  {9, 0x7, 31},  {9, 0x6, 47},  {9, 0x5, 55},  {9, 0x4, 59},  {9, 0x3, 27},  {9, 0x2, 39},
    {9, 0x1, 0},
};

template <std::size_t N, std::size_t M>
void fill(InterVlcEntry (&table)[N], int bits, const Code (&codes)[M]) {
  for (auto& e : table) e = InterVlcEntry{0, 0};
  for (const Code& c : codes) {
    const int free = bits - c.len;
    const std::size_t first = static_cast<std::size_t>(c.code) << free;
    for (std::size_t i = 0; i < (std::size_t{1} << free); ++i) table[first + i] = InterVlcEntry{c.value, c.len};
  }
}

InterVlcTables build() {
  InterVlcTables t{};
  fill(t.mbTypeP, 6, kB3);
  fill(t.mbTypeB, 6, kB4);
  fill(t.codedBlockPattern, 9, kB9);
  return t;
}

}  // namespace

const InterVlcTables& interVlcTables() {
  static const InterVlcTables tables = build();
  return tables;
}

}  // namespace vbim::ipu
