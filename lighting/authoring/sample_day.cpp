#include "lighting/authoring/sample_day.hpp"

namespace vbim::lighting {

TechniqueAStreamSettings sampleDaySettings(unsigned threads) {
  TechniqueAStreamSettings s;
  // --procedural --size 256 --cell-size 20 (a given cell size: the DEM override and the procedural
  // terrain's cells), seed 1 and 900 m of relief as `vbim author`'s defaults.
  s.terrain.cellSize = 20.0;
  s.terrain.cellSizeGiven = true;
  s.terrain.procedural.size = 256;
  s.terrain.procedural.seed = 1;
  s.terrain.procedural.reliefMetres = 900.0;
  s.terrain.procedural.cellSize = s.terrain.cellSize;
  // --sky-width 128 --frame-count 24 --start-hour 0 --end-hour 24
  s.base.skyWidth = 128;
  s.base.frames = 24;
  s.base.startHour = 0;
  s.base.endHour = 24;
  s.variants = {weatherVariant("clear", s.base)};
  // --exposure -1 --q 6 --fps 1
  s.tone.exposure = -1;
  s.stream.encoder.qscale = 6;
  s.stream.gameFps = {1, 1};
  s.threads = threads;
  return s;
}

}  // namespace vbim::lighting
