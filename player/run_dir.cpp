#include "player/run_dir.hpp"

#include <cstdio>

#include "gs/arrival_source.hpp"
#include "player/ipu_command_log.hpp"
#include "player/replay.hpp"
#include "player/report.hpp"
#include "runtime/error.hpp"

namespace vbim::player {

namespace {

std::ofstream openIn(const std::filesystem::path& dir, const char* name) {
  std::ofstream f(dir / name, std::ios::binary);
  if (!f) throw Error((dir / name).string() + ": cannot create the file");
  return f;
}

}  // namespace

RunDirWriter::RunDirWriter(Player& player, const std::filesystem::path& dir, RunDirOptions options)
    : player_(player),
      dir_(dir),
      options_(std::move(options)),
      hashes_(openIn(dir, "hashes.txt")),
      timeline_(openIn(dir, "timeline.csv")),
      arrivals_(openIn(dir, "arrivals.csv")),
      nextAt_(options_.at.begin()) {
  timeline_ << timelineHeader();
  arrivals_ << arrivalsHeader();
  const VsyncClock vsyncs = player_.pipeline().lightmap().clock();
  player_.pipeline().setArrivalHook([this, vsyncs](bool sky, int variant, std::int64_t seq, Tick readyAt) {
    arrivals_ << arrivalLine(ReplayArrival{gs::firstVsyncAtOrAfter(vsyncs, readyAt), sky, variant, seq});
  });
  if (options_.ipuCommands) {
    ipuCommands_ = openIn(dir_, "ipu_commands.csv");
    ipuCommands_ << ipuCommandsHeader();
    player_.pipeline().setIpuCommandHook(
        [this](int stream, int variant, const ee::CompressedPicture& pic, const ipu::TimedPicture& tp) {
          ipuCommands_ << ipuCommandLines(stream, variant, pic, tp);
        });
  }
  std::filesystem::create_directories(dir_ / "frames");
  Player::Sink before = player_.sink();
  player_.setSink([this, before](const VsyncRow& row, const Rgba8Image& lm, const Rgba8Image* sky) {
    if (before) before(row, lm, sky);
    onVsync(row, lm, sky);
  });
  if (options_.writeImage && options_.pictureQueue > 0) pictures_.emplace(options_.writeImage, options_.pictureQueue);
  // The trace streams to its files as the run goes (memory independent of the run's length).
  if (options_.trace) {
    traceJson_ = openIn(dir_, "trace.json");
    traceVcd_ = openIn(dir_, "signals.vcd");
    player_.tracer().streamTo(traceJson_, traceVcd_, options_.traceDetail);
  }
}

void RunDirWriter::onVsync(const VsyncRow& row, const Rgba8Image& lightmap, const Rgba8Image* sky) {
  hashes_ << hashesLine(row);
  ++presented_;
  timeline_ << timelineLine(row);
  readErrors_.onVsync(row.at, player_.pipeline().drive().stats().retries);
  if (options_.onRow) options_.onRow(row);
  bool shoot = options_.every > 0 && row.vsync % options_.every == 0;
  while (nextAt_ != options_.at.end() && *nextAt_ <= row.at) {
    shoot = true;
    ++nextAt_;
  }
  if (!shoot || !options_.writeImage) return;
  char name[64];
  std::snprintf(name, sizeof name, "%06lld", static_cast<long long>(row.vsync));
  const std::string suffix = std::string(name) + "." + options_.imageExtension;
  writePicture(dir_ / "frames" / ("lightmap_" + suffix), lightmap);
  if (sky != nullptr) writePicture(dir_ / "frames" / ("sky_" + suffix), *sky);
  ++images_;
}

void RunDirWriter::writePicture(std::filesystem::path path, const Rgba8Image& picture) {
  if (pictures_) {
    pictures_->push(std::move(path), picture);
  } else {
    copy_.width = picture.width;
    copy_.height = picture.height;
    copy_.pixels.assign(picture.pixels.begin(), picture.pixels.end());
    options_.writeImage(path, copy_);
  }
}

void RunDirWriter::flushPictures() {
  if (pictures_) pictures_->drain();
}

void RunDirWriter::finish(const json::Value* run) {
  flushPictures();
  hashes_.close();
  timeline_.close();
  arrivals_ << arrivalsEndLine(presented_);
  arrivals_.close();
  if (options_.ipuCommands) ipuCommands_.close();
  if (!hashes_ || !timeline_ || !arrivals_ || (options_.ipuCommands && !ipuCommands_)) {
    throw Error(dir_.string() + ": cannot write the run's text files");
  }
  {
    std::ofstream f = openIn(dir_, "faults.csv");
    writeFaultSpansCsv(
        f, mergeFaultSpans(plannedFaultSpans(player_.options().faults, player_.duration()), readErrors_.spans()));
    if (!f) throw Error((dir_ / "faults.csv").string() + ": cannot write the file");
  }
  {
    std::ofstream f = openIn(dir_, "stats.json");
    writeStatsJson(player_, f, run);
    if (!f) throw Error((dir_ / "stats.json").string() + ": cannot write the file");
  }
  if (options_.trace) {
    player_.tracer().finish();
    traceJson_.close();
    traceVcd_.close();
    if (!traceJson_ || !traceVcd_) throw Error((dir_ / "trace.json").string() + ": cannot write the trace files");
  }
}

}  // namespace vbim::player
