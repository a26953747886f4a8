#include "runs/config_run.hpp"

#include <optional>
#include <sstream>

#include "config/fault_plan_toml.hpp"
#include "config/params_toml.hpp"
#include "gs/setup_listing.hpp"
#include "iop/fault_plan.hpp"
#include "player/platform_config.hpp"
#include "runs/console_check.hpp"
#include "runtime/param_table.hpp"
#include "streams/disc/stream_disc.hpp"

namespace vbim::runs {

ConfigResult configRun(const ConfigRequest& r) {
  player::PlatformConfig params;
  ParamTable table;
  player::describeParams(table, params);
  std::optional<gs::VramLayout> vram;  // checked with a config or a stream (the GS setup needs the stream)
  if (!r.check.empty()) {
    config::applyTomlFile(table, r.check);
    player::validate(params);
  }
  // The stream, opened once: its frame sizes for the GS checks, and the disc a fault plan's file
  // names are looked up on.
  std::optional<streams::StreamDisc> given;
  if (!r.stream.empty()) given = streams::openStreamDisc(r.stream, r.file);
  const streams::StreamDisc* disc = given ? &*given : nullptr;
  const PresentedSizes presented = presentedSizes(disc);
  if (!r.check.empty() || disc != nullptr) vram = checkPresenters(presented, params, r.check);
  const bool checking = !r.check.empty() || !r.stream.empty() || !r.faults.empty();
  const bool printing = !checking || r.gsSetup || r.markdown || r.defaults || r.effective;
  ConfigResult result;
  std::ostringstream verdict;
  if (!r.faults.empty()) {
    // With a stream, entries that name a file (file = "\\DATA\\DAY.VBI;1") are looked up on that
    // disc and LBAs checked against its size, as play does.
    const iop::FaultPlan plan = config::loadFaultPlan(r.faults, disc != nullptr ? disc->disc.get() : nullptr);
    verdict << r.faults << ": " << plan.faults.size() << " fault(s), valid\n";
  }
  if (!r.check.empty() || !r.stream.empty()) {
    verdict << (r.check.empty() ? std::string("the default platform config") : r.check)
            << (r.stream.empty() ? "" : " with " + r.stream) << ": valid";
    if (printing) verdict << "; the " << (r.gsSetup ? "GS setup" : "effective config") << " follows";
    verdict << "\n";
  }
  result.verdict = verdict.str();
  if (!printing) return result;
  std::ostringstream doc;
  if (r.gsSetup && r.format != "markdown") {
    gs::writeGsPackets(doc, params.gs, *vram, presented.lightmap, presented.sky,
                       r.format == "c" ? gs::PacketFormat::C : gs::PacketFormat::Gif, r.stream);
  } else if (r.gsSetup) {
    gs::writeGsSetup(doc, params.gs, *vram, presented.lightmap, presented.sky);
  } else if (r.markdown) {
    table.writeMarkdown(doc);
  } else {
    doc << "# vbim platform config: every timing constant, its default and its source.\n"
        << "# Pass a copy to `vbim play --config FILE`; keys left out keep their defaults.\n\n";
    table.writeToml(doc);
  }
  result.document = doc.str();
  return result;
}

}  // namespace vbim::runs
