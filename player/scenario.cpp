#include "player/scenario.hpp"

#include <sstream>
#include <stdexcept>

#include "iop/file_disc.hpp"
#include "player/report.hpp"

namespace vbim::player {

Run::Run(std::shared_ptr<iop::SectorSource> disc, const iop::DiscFile& file, PlayerOptions options)
    : disc_(std::move(disc)), player_(*disc_, file, std::move(options)) {
  player_.setSink([this](const VsyncRow& row, const Rgba8Image&, const Rgba8Image*) { rows_.push_back(row); });
}

std::vector<std::uint64_t> Run::hashes() const {
  std::vector<std::uint64_t> h;
  h.reserve(rows_.size());
  for (const VsyncRow& r : rows_) h.push_back(r.hash);
  return h;
}

const VsyncRow& Run::rowAt(Tick t) const {
  for (const VsyncRow& r : rows_) {
    if (r.at >= t) return r;
  }
  throw std::out_of_range("no vsync at or after " + std::to_string(toSeconds(t)) + " s recorded yet");
}

std::string Run::statsJson() const {
  std::ostringstream s;
  writeStatsJson(player_, s);
  return s.str();
}

Scenario Scenario::bareFile(const std::string& path) {
  auto disc = iop::bareFileDisc(path);
  const iop::DiscFile file = disc->file();
  return Scenario(std::move(disc), file);
}

Scenario::Scenario(std::shared_ptr<iop::SectorSource> disc, iop::DiscFile file)
    : disc_(std::move(disc)), file_(std::move(file)) {}

Scenario& Scenario::config(const PlatformConfig& c) {
  options_.config = c;
  return *this;
}

Scenario& Scenario::faults(const iop::FaultPlan& plan) {
  options_.faults = plan;
  return *this;
}

Scenario& Scenario::stall(Tick at, Tick duration) {
  iop::Fault f;
  f.kind = iop::Fault::Kind::Stall;
  f.at = at;
  f.duration = duration;
  options_.faults.faults.push_back(f);
  return *this;
}

Scenario& Scenario::readError(std::int64_t fileSector, std::int64_t attempts) {
  iop::Fault f;
  f.kind = iop::Fault::Kind::ReadError;
  f.lba = file_.lba + fileSector;
  f.attempts = attempts;
  options_.faults.faults.push_back(f);
  return *this;
}

Scenario& Scenario::seed(std::uint64_t s) {
  options_.seed = s;
  return *this;
}

Scenario& Scenario::branch(Tick at, int variant) {
  options_.branches.push_back(Branch{at, variant});
  return *this;
}

Scenario& Scenario::policy(const std::string& catchup) {
  options_.config.gs.catchup = catchup;
  return *this;
}

Scenario& Scenario::kernels(Kernels k) {
  options_.kernels = k;
  return *this;
}

Scenario& Scenario::trace(bool on) {
  options_.trace = on;
  return *this;
}

std::unique_ptr<Run> Scenario::start(Tick duration) const {
  PlayerOptions o = options_;
  o.duration = duration;
  return std::make_unique<Run>(disc_, file_, std::move(o));
}

}  // namespace vbim::player
