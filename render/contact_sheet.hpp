// The day on one page: the rendered frames as thumbnails in a grid, each framed by what the
// lightmap was doing since the previous one (red: late, the frame due had not arrived; orange:
// catching up, blending toward a frame that came late; green: waiting, the GS has no frame yet, so
// the picture is black; grey: on time) and labelled with its
// simulated time, that state and the drive faults in its interval (stall, read error, ...). Under
// the grid a strip over the whole run, one column per slice of vsyncs, in the same colours, with a
// white tick at every thumbnail's time; under it the drive's faults on the same time axis; last a
// legend naming every colour used. Text is drawn with render/bitmap_font.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "player/fault_spans.hpp"
#include "runtime/image.hpp"

namespace vbim::render {

// In order of precedence: a tile or a strip column shows the greatest over its vsyncs.
enum class Moment : std::uint8_t {
  OnTime,   // the lightmap shows the frame due
  Waiting,  // no frame has arrived yet and none is due (the start of a run, the drive spinning up)
  CatchUp,  // blending toward a frame that arrived after it was due
  Late,     // the frame due has not arrived (it may be the first: nothing shown and late)
};

const char* toString(Moment m);  // "on time", "waiting", "catch-up", "late"

struct SheetTile {
  std::int64_t vsync = 0;
  double timeS = 0;  // simulated time of the frame
  Rgba8Image picture;
  Moment moment = Moment::OnTime;   // the worst state since the previous tile
  std::vector<std::string> faults;  // drive faults (FaultSpan::kind) in that interval, each once
};

struct SheetRun {
  std::vector<Moment> states;             // one per vsync of the run (index = vsync); empty: no strip
  double seconds = 0;                     // the run's length (the time at states.size())
  std::vector<player::FaultSpan> faults;  // the drive's faults (faults.csv); a strip when any
};

Rgba8Image contactSheet(const std::vector<SheetTile>& tiles, const SheetRun& run, int columns, int thumbWidth);

// The colour a fault kind is shown in (the sheet's fault strip and its legend).
void faultColour(const std::string& kind, std::uint8_t rgb[3]);

// Box-filter downscale to `width` (height keeps the aspect ratio).
Rgba8Image downscale(const Rgba8Image& in, int width);

}  // namespace vbim::render
