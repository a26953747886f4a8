// libFuzzer target: the ISO 9660 reader (streams/disc, iso9660_*) on any image. Opening it, listing
// its files and looking files up must give a DiscError or an answer, never a crash, an out-of-bounds
// read or a walk that does not end.
#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "iop/error.hpp"
#include "streams/disc/iso_disc.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/vbim_iso_fuzzer_" + std::to_string(getpid()) + ".iso";
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    vbim::streams::IsoDisc disc(path);
    try {
      (void)disc.files();  // what `vbim play disc.iso` does first
    } catch (const vbim::Error&) {
    }
    for (const char* name : {"\\VIDEO\\DAY.PSS;1", "\\SYSTEM.CNF;1", "\\A\\B\\C.BIN;1"}) {
      if (auto f = disc.find(name)) {
        std::array<std::uint8_t, vbim::iop::kSectorBytes> sector{};
        (void)disc.read(f->lba, vbim::iop::SectorSpan(sector));
      }
    }
  } catch (const vbim::Error&) {
  }
  return 0;
}
