// The IPU's command words as the EE writes them to IPU_CMD (0x10002000), and the IPU_CTRL value it
// sets for a picture, for the command log of `vbim play --trace-detail ipu` (docs/run-files.md,
// "ipu_commands.csv"; docs/porting.md, "Diffing the IPU commands").
//
// Layouts (T-IPU Commands and IO_Regs; P-IPU IPU.h tIPU_CMD_IDEC, tIPU_CMD_BDEC, tIPU_CMD_CSC,
// tIPU_CTRL, and IPU.cpp IPUCMD_WRITE, ipuBCLR, ipuSETTH, ipuVDEC): the code in bits 28-31
//   BCLR  0  BP 0-6 (the bit position in the first qword)
//   IDEC  1  FB 0-5, QSC 16-20, DTD 24, SGN 25, DTE 26, OFM 27
//   BDEC  2  FB 0-5, QSC 16-20, DT 25, DCR 26, MBI 27
//   VDEC  3  FB 0-5, TBL 26-27 (0 address increment, 1 macroblock type, 2 motion code, 3 dmvector)
//   FDEC  4  FB 0-5
//   SETIQ 5  FB 0-5, IQM 27 (0 intra, 1 non-intra matrix)
//   SETVQ 6  -
//   CSC   7  MBC 0-10, DTE 26, OFM 27
//   PACK  8  MBC 0-10, DTE 26, OFM 27 (not issued by vbim)
//   SETTH 9  TH0 0-8, TH1 16-24
//   IPU_CTRL: IDP 16-17, AS 20, IVF 21, QST 22, MP1 23, PCT 24-26
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ipu/headers.hpp"
#include "runtime/clock.hpp"

namespace vbim::ipu {

enum class IpuOpcode : std::uint8_t {
  kBclr = 0,
  kIdec = 1,
  kBdec = 2,
  kVdec = 3,
  kFdec = 4,
  kSetiq = 5,
  kSetvq = 6,
  kCsc = 7,
  kPack = 8,
  kSetth = 9
};

// VDEC's TBL: which variable-length table it decodes with.
enum class VdecTable : std::uint8_t { kAddressIncrement = 0, kMacroblockType = 1, kMotionCode = 2, kDmVector = 3 };

inline IpuOpcode opcodeOf(std::uint32_t word) {
  return static_cast<IpuOpcode>(word >> 28);
}
const char* opcodeName(IpuOpcode op);  // "BCLR", "IDEC", ...

std::uint32_t bclrWord(int bp);
std::uint32_t idecWord(int fb, int qsc, bool dtd, bool sgn, bool dte, bool ofm);
std::uint32_t bdecWord(int fb, int qsc, bool dt, bool dcr, bool mbi);
std::uint32_t vdecWord(int fb, VdecTable tbl);
std::uint32_t fdecWord(int fb);
std::uint32_t setiqWord(int fb, bool nonIntra);
std::uint32_t setvqWord();
std::uint32_t cscWord(int mbc, bool dte, bool ofm);
std::uint32_t setthWord(int th0, int th1);

// The fields of a command word as `NAME=value` pairs separated by spaces ("FB=39 QSC=4 DTD=0 ...").
std::string commandFields(std::uint32_t word);

// IPU_CTRL as the EE sets it before a picture's commands (docs/porting.md, "IPU: BCLR, IDEC per
// slice, CSC", step 1): IDP, AS, IVF, QST from the picture coding extension, MP1 for an MPEG-1
// sequence, PCT the picture coding type.
std::uint32_t ipuCtrl(const SequenceHeader& seq, const PictureHeader& pic);
std::string ctrlFields(std::uint32_t ctrl);  // "IDP=0 AS=0 IVF=0 QST=0 MP1=0 PCT=1"

// One slice of a picture as the EE issues IDEC for it: the address of its first macroblock, the
// offset of its start code in the picture's bytes, its quantiser_scale_code, and the bits IDEC's FB
// must skip from the start code to the first macroblock's macroblock_type (the start code, the slice
// header and the first macroblock_address_increment: 39 for the samples' slices).
struct SliceStart {
  std::uint32_t address = 0;
  std::size_t offset = 0;
  int qsc = 0;
  int fb = 0;
};
// The slices of `bytes` whose header reads (picture parameters from the decoder's last picture:
// `seq`, `pic`, and the frame's macroblock width and height). Slices cut short are left out.
std::vector<SliceStart> sliceStarts(std::span<const std::uint8_t> bytes, const SequenceHeader& seq,
                                    const PictureHeader& pic, int mbWidth, int mbHeight);

// A command the timed IPU issued: its word and its time on the simulated clock (issued by the EE;
// done: the IPU's last output of it pushed, or for a command without output, its answer).
struct IssuedCommand {
  std::uint32_t word = 0;
  Tick begin = 0;
  Tick end = 0;
};

}  // namespace vbim::ipu
