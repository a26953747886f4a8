#include "plots/plplot_page.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>

#include "runtime/error.hpp"

namespace vbim::plots {

namespace {

std::mutex& plplotMutex() {
  static std::mutex m;
  return m;
}

const char* deviceName(Device d) {
  return d == Device::Png ? "pngcairo" : "svgcairo";
}

// The file a fatal PLplot error concerns (set while a page exists, under plplotMutex()).
const std::string* gFileBeingDrawn = nullptr;

int onPlplotExit(const char* message) {
  std::cerr << "vbim: PLplot failed while drawing " << (gFileBeingDrawn ? *gFileBeingDrawn : std::string("a plot"))
            << ": " << message << "\n";
  return 1;  // PLplot then prints its own message and exits with this status
}

bool listsDevice(const std::filesystem::path& driverInfo, std::string_view device) {
  std::ifstream in(driverInfo);
  for (std::string line; std::getline(in, line);)
    if (line.starts_with(device) && line.size() > device.size() && line[device.size()] == ':') return true;
  return false;
}

// PLplot loads its devices at run time from a drivers directory (PLPLOT_DRV_DIR, else the one it
// was built with): a `<driver>.driver_info` file lists a driver's devices beside `<driver>.so`.
// A device it cannot find makes PLplot prompt on stdin and then exit, and a directory without
// drivers makes it exit: both are checked here first, with the package to install.
void requireDevice(Device device, const std::string& file) {
  const char* env = std::getenv("PLPLOT_DRV_DIR");
  // Set but empty is PLplot's choice too (a directory it cannot open): the check below fails it.
  const std::filesystem::path dir = env != nullptr ? env : VBIM_PLPLOT_DRV_DIR;
  const char* name = deviceName(device);
  std::error_code ec;
  if (dir.empty() || !std::filesystem::exists(dir / "cairo.so", ec) || !listsDevice(dir / "cairo.driver_info", name)) {
    throw Error(file + ": PLplot's cairo driver (device " + name + ") is not installed in '" + dir.string() + "'" +
                ": apt-get install plplot-driver-cairo" + (env != nullptr ? " (or unset PLPLOT_DRV_DIR)" : ""));
  }
  const char* menus[128];
  const char* names[128];
  const char** menuList = menus;
  const char** nameList = names;
  int count = 128;
  plgDevs(&menuList, &nameList, &count);
  for (int i = 0; i < count; ++i)
    if (std::strcmp(names[i], name) == 0) return;
  throw Error(file + ": PLplot does not offer the " + name + " device: apt-get install plplot-driver-cairo");
}

}  // namespace

PlplotPage::PlplotPage(Device device, int width, int height, std::string file)
    : lock_(plplotMutex()), device_(device), file_(std::move(file)) {
  try {
    requireDevice(device_, file_);
    memory_ = open_memstream(&bytes_, &size_);
    if (memory_ == nullptr) throw Error(file_ + ": cannot open a memory stream for the plot: " + std::strerror(errno));
    gFileBeingDrawn = &file_;
    plsexit(onPlplotExit);
    plgstrm(&previous_);
    plmkstrm(&stream_);
    if (stream_ < 0) throw Error(file_ + ": PLplot has no free stream");
    plsError(&errorCode_, errorMessage_);
    plsdev(deviceName(device_));
    plsfile(memory_);
    plspage(0, 0, width, height, 0, 0);
    plscmap0n(kColourSlots);
    plscolbg(255, 255, 255);
    plinit();
    drawing_ = true;
    check();
    pladv(0);
  } catch (...) {
    end();
    throw;
  }
}

PlplotPage::~PlplotPage() {
  end();
  std::free(bytes_);
}

void PlplotPage::end() {
  if (stream_ >= 0) {
    plend1();  // with drawing_: writes the picture and closes memory_
    stream_ = -1;
    plsstrm(previous_);
  }
  if (!drawing_ && memory_ != nullptr) std::fclose(memory_);
  memory_ = nullptr;
  drawing_ = false;
  plsexit(nullptr);
  gFileBeingDrawn = nullptr;
}

void PlplotPage::check() const {
  if (errorCode_ != 0) {
    const std::string_view m(errorMessage_);
    const auto first = m.find_first_not_of("\n *"), last = m.find_last_not_of("\n *");
    throw Error(file_ + ": PLplot: " + std::string(first == m.npos ? "error" : m.substr(first, last - first + 1)));
  }
}

std::string PlplotPage::finish() {
  check();
  end();
  check();
  // PLplot's cairo devices ignore write errors; a complete picture starts with its signature.
  const std::string_view signature = device_ == Device::Png ? std::string_view("\x89PNG\r\n\x1a\n", 8) : "<?xml";
  std::string out(bytes_ != nullptr ? bytes_ : "", size_);
  if (!out.starts_with(signature)) throw Error(file_ + ": PLplot wrote no complete picture");
  return out;
}

}  // namespace vbim::plots
