// GS local memory as a budget: 4 MiB of embedded DRAM in 512 pages of 8 KiB (P-GS m_vmsize;
// docs/hardware.md#vram). Buffers are placed on page boundaries, as FRAME.FBP (9 bits, page units)
// requires for frame buffers and as is usual for textures. A page holds 64x32 pixels of PSMCT32 /
// PSMCT24 / PSMZ32 / PSMZ24 and 64x64 of PSMCT16 / PSMZ16, so a buffer takes
// ceil(w / page_w) * ceil(h / page_h) pages.
//
// The model keeps pixel data in linear images (not the GS's swizzled page order, which nothing
// here observes); this class decides whether a layout fits and where each buffer starts.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vbim::gs {

enum class Psm : std::uint8_t { Ct32, Ct24, Ct16, Z32, Z24, Z16 };

// "ct32", "ct24", "ct16", "z32", "z24", "z16"; throws GsError on an unknown name.
Psm psmByName(std::string_view name);
const char* psmName(Psm psm);  // "PSMCT32", ...

struct PageShape {
  int width;
  int height;
};
PageShape pageShape(Psm psm);
int pagesFor(Psm psm, int width, int height);

inline constexpr int kVramPages = 512;
inline constexpr int kPageBytes = 8192;
inline constexpr int kVramBytes = kVramPages * kPageBytes;  // 4 MiB
inline constexpr int kBlocksPerPage = 32;                   // 256-byte blocks (TBP0/DBP units)

struct VramRequest {
  std::string name;  // "lightmap", "staging", "sky", "frame0", "z"
  Psm psm;
  int width;
  int height;
};

struct VramRegion {
  std::string name;
  Psm psm;
  int width;
  int height;
  int firstPage;  // FRAME.FBP
  int pages;
  int basePointer() const { return firstPage * kBlocksPerPage; }  // TEX0.TBP0 / BITBLTBUF.DBP
};

class VramLayout {
 public:
  // Places every request in order, page-aligned. Throws GsError listing every buffer with its
  // size in pages and bytes, the total needed and the 512 pages available, if they do not fit;
  // also if a size is not positive or exceeds the GS's 2048-pixel coordinate space.
  static VramLayout place(const std::vector<VramRequest>& requests);

  const std::vector<VramRegion>& regions() const { return regions_; }
  const VramRegion& region(std::string_view name) const;  // throws GsError if absent
  bool has(std::string_view name) const;
  int pagesUsed() const { return used_; }
  int pagesFree() const { return kVramPages - used_; }
  // One line per buffer, then the total: for reports and error messages.
  std::string describe() const;

 private:
  std::vector<VramRegion> regions_;
  int used_ = 0;
};

}  // namespace vbim::gs
