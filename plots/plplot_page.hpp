// One picture drawn by PLplot into memory with one of its cairo devices (pngcairo, svgcairo), on a
// PLplot stream of its own. While a PlplotPage exists it is PLplot's current stream; PLplot keeps
// its streams and error handlers in process-wide state, so pages are drawn one at a time (a
// process-wide lock, held from construction to destruction) and the stream that was current before
// is current again afterwards.
//
// Errors: PLplot reports recoverable errors ("plabort") into this page (check() and finish() turn
// them into Error naming the file). Its fatal errors ("plexit": out of memory, a driver that
// cannot be loaded) end the process; the checks made before PLplot starts (the cairo driver is
// installed, the output is only memory) keep the foreseeable failures out of that path, and the
// exit handler installed here names the file being drawn before PLplot exits.
#pragma once

#include <cstdio>
#include <mutex>
#include <string>

#include <plplot/plplot.h>

namespace vbim::plots {

enum class Device { Png, Svg };

class PlplotPage {
 public:
  // Starts a `width` x `height` page (pixels for PNG, points for SVG) on a white background.
  // `file` names the picture in error messages. Throws Error when the device is not installed.
  PlplotPage(Device device, int width, int height, std::string file);
  ~PlplotPage();
  PlplotPage(const PlplotPage&) = delete;
  PlplotPage& operator=(const PlplotPage&) = delete;

  // cmap0 has this many colour slots; slot 0 is the background.
  static constexpr int kColourSlots = 64;

  // Throws Error if PLplot has reported an error on this page.
  void check() const;
  // Ends the page and returns the picture's bytes (a PNG or SVG file). Throws Error on an error.
  std::string finish();

 private:
  void end();

  std::unique_lock<std::mutex> lock_;
  Device device_;
  std::string file_;
  FILE* memory_ = nullptr;  // an open_memstream; PLplot closes it when its stream ends
  char* bytes_ = nullptr;
  std::size_t size_ = 0;
  PLINT previous_ = 0;
  PLINT stream_ = -1;
  bool drawing_ = false;  // plinit ran: plend1 will write the picture and close memory_
  PLINT errorCode_ = 0;
  char errorMessage_[1024] = {};  // PLplot writes into it with sprintf: generously sized
};

}  // namespace vbim::plots
