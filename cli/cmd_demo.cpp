// vbim demo: the README's main job. Until the pipeline exists (issues #7 and #9) it runs the
// kernel's exercise model (runtime/shape_model.hpp) for 60 simulated seconds with a 500 ms stall
// and writes its trace and waveform, so the end-to-end part that exists can be opened and looked at.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/command.hpp"
#include "cli/output_dir.hpp"
#include "runtime/shape_model.hpp"
#include "runtime/trace.hpp"

namespace vbim::cli {

namespace {

struct DemoOptions {
  std::string out = "out/demo";
  double seconds = 60.0;
  bool force = true;  // the demo owns out/demo and replaces it
};

void runDemo(const DemoOptions& o) {
  ShapeModelSettings s;
  s.duration = fromSeconds(o.seconds);
  Tracer tracer;
  const auto wall0 = std::chrono::steady_clock::now();  // host time, for the summary only
  const ShapeModelResult r = runShapeModel(s, &tracer);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();

  OutputDir dir(o.out, o.force);
  {
    std::ofstream f(dir.path("trace.json"), std::ios::binary);
    tracer.writeChromeJson(f);
  }
  {
    std::ofstream f(dir.path("signals.vcd"), std::ios::binary);
    tracer.writeVcd(f);
  }
  {
    std::ofstream f(dir.path("summary.txt"), std::ios::binary);
    f << "model: producer every 13.9 us -> FIFO depth 8 -> consumer 20 us/token, 59.94 Hz vsync\n"
      << "fault: producer suspended " << toMs(s.stallFor) << " ms at " << toSeconds(s.stallAt) << " s\n"
      << "simulated: " << toSeconds(r.end) << " s\n"
      << "produced: " << r.produced << "\nconsumed: " << r.consumed << "\nvsyncs: " << r.vsyncs
      << "\nstarved vsyncs: " << r.starvedVsyncs << "\nproducer blocked by a full FIFO: " << r.producerBlocked
      << "\nscheduler events: " << r.events << "\n";
  }
  dir.commit();

  std::cout << "vbim demo: the full pipeline is not built yet (issues #3-#9); ran the kernel model instead.\n"
            << "  simulated " << toSeconds(r.end) << " s in " << wall << " s of host time (" << r.events << " events, "
            << static_cast<double>(r.events) / wall / 1e6 << " M events/s)\n"
            << "  consumed " << r.consumed << " tokens; " << r.starvedVsyncs << " of " << r.vsyncs
            << " vsyncs saw no progress (the injected 500 ms stall)\n"
            << "Open:\n"
            << "  " << o.out << "/trace.json   in https://ui.perfetto.dev (busy spans, FIFO occupancy)\n"
            << "  " << o.out << "/signals.vcd  in GTKWave\n"
            << "  " << o.out << "/summary.txt\n";
}

}  // namespace

void addDemo(CLI::App& app) {
  auto opts = std::make_shared<DemoOptions>();
  auto* cmd = app.add_subcommand("demo", "Run the main job on built-in defaults and write everything to out/demo/");
  cmd->add_option("--out", opts->out, "Output directory (replaced)")->capture_default_str();
  cmd->add_option("--seconds", opts->seconds, "Simulated seconds")
      ->check(CLI::Range(0.001, 86400.0))
      ->capture_default_str();
  cmd->callback([opts] { runDemo(*opts); });
}

}  // namespace vbim::cli
