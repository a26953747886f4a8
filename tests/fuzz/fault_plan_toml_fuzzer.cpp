// libFuzzer target: the fault-plan TOML reader on any text, against a small disc with one named
// file. A plan it accepts is armed on a drive that then reads for a simulated second: every valid
// plan must run in bounded time and memory (faults are made as the clock reaches them).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

#include "config/fault_plan_toml.hpp"
#include "iop/drive.hpp"
#include "iop/fault_plan.hpp"
#include "iop/memory_disc.hpp"
#include "runtime/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vbim::iop::MemoryDisc disc(100'000);
  disc.addPatternFile("\\AUDIO\\MUSIC.PSS;1", 50'000, 1000);
  vbim::iop::FaultPlan plan;
  try {
    plan =
        vbim::config::parseFaultPlan(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml", &disc);
  } catch (const vbim::Error&) {
    return 0;
  }
  vbim::Scheduler s;
  vbim::iop::Drive drive(s, disc, vbim::iop::DriveParams{}, vbim::Rng(1).fork("iop"));
  vbim::iop::applyFaults(s, drive, plan, vbim::Rng(1).fork("faults"));
  auto c = std::make_shared<vbim::iop::DriveCommand>();
  c->sectors = 64;
  drive.enqueue(c);
  s.runUntil(vbim::fromMs(1000));
  return 0;
}
