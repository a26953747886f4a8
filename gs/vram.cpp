#include "gs/vram.hpp"

#include <sstream>

#include "gs/error.hpp"

namespace vbim::gs {

Psm psmByName(std::string_view name) {
  if (name == "ct32") return Psm::Ct32;
  if (name == "ct24") return Psm::Ct24;
  if (name == "ct16") return Psm::Ct16;
  if (name == "z32") return Psm::Z32;
  if (name == "z24") return Psm::Z24;
  if (name == "z16") return Psm::Z16;
  throw GsError("unknown pixel format '" + std::string(name) + "' (expected ct32, ct24, ct16, z32, z24 or z16)");
}

const char* psmName(Psm psm) {
  switch (psm) {
    case Psm::Ct32:
      return "PSMCT32";
    case Psm::Ct24:
      return "PSMCT24";
    case Psm::Ct16:
      return "PSMCT16";
    case Psm::Z32:
      return "PSMZ32";
    case Psm::Z24:
      return "PSMZ24";
    case Psm::Z16:
      return "PSMZ16";
  }
  return "?";
}

PageShape pageShape(Psm psm) {
  // P-GS pageOffset table dimensions: 32-bit formats 64x32 per page, 16-bit formats 64x64.
  return (psm == Psm::Ct16 || psm == Psm::Z16) ? PageShape{64, 64} : PageShape{64, 32};
}

int pagesFor(Psm psm, int width, int height) {
  const PageShape p = pageShape(psm);
  return ((width + p.width - 1) / p.width) * ((height + p.height - 1) / p.height);
}

namespace {

std::string mib(long long bytes) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(2);
  s << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MiB";
  return s.str();
}

std::string line(const std::string& name, Psm psm, int w, int h, int pages) {
  std::ostringstream s;
  s << name << " " << w << "x" << h << " " << psmName(psm) << " = " << pages << " pages ("
    << static_cast<long long>(pages) * kPageBytes / 1024 << " KiB)";
  return s.str();
}

}  // namespace

VramLayout VramLayout::place(const std::vector<VramRequest>& requests) {
  VramLayout out;
  std::ostringstream listing;
  int total = 0;
  for (const VramRequest& r : requests) {
    if (r.width <= 0 || r.height <= 0 || r.width > 2048 || r.height > 2048) {
      throw GsError("VRAM buffer '" + r.name + "' is " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                    ": each side must be 1..2048 pixels (the GS coordinate space)");
    }
    const int pages = pagesFor(r.psm, r.width, r.height);
    if (!out.regions_.empty()) listing << ", ";
    listing << line(r.name, r.psm, r.width, r.height, pages);
    out.regions_.push_back(VramRegion{r.name, r.psm, r.width, r.height, total, pages});
    total += pages;
  }
  if (total > kVramPages) {
    throw GsError("VRAM layout does not fit: it needs " + std::to_string(total) + " pages (" +
                  mib(static_cast<long long>(total) * kPageBytes) + ") but the GS has " + std::to_string(kVramPages) +
                  " pages of 8 KiB (" + mib(kVramBytes) + "), " + std::to_string(total - kVramPages) +
                  " pages too many: " + listing.str());
  }
  out.used_ = total;
  return out;
}

const VramRegion& VramLayout::region(std::string_view name) const {
  for (const VramRegion& r : regions_) {
    if (r.name == name) return r;
  }
  throw GsError("no VRAM buffer named '" + std::string(name) + "'");
}

bool VramLayout::has(std::string_view name) const {
  for (const VramRegion& r : regions_) {
    if (r.name == name) return true;
  }
  return false;
}

std::string VramLayout::describe() const {
  std::ostringstream s;
  for (const VramRegion& r : regions_) {
    s << "page " << r.firstPage << ": " << line(r.name, r.psm, r.width, r.height, r.pages) << "\n";
  }
  s << "used " << used_ << " of " << kVramPages << " pages (" << mib(static_cast<long long>(used_) * kPageBytes)
    << " of " << mib(kVramBytes) << "), " << pagesFree() << " free\n";
  return s.str();
}

}  // namespace vbim::gs
