#include "player/report.hpp"

#include <algorithm>
#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "player/frame_hash.hpp"
#include "runtime/json.hpp"

namespace vbim::player {

namespace {

// Exact decimal of t / kBusHz to 6 places, rounded down: integer arithmetic only. Writes at most
// 40 chars at out and returns the end.
char* formatSeconds(char* out, Tick t) {
  const std::int64_t us = static_cast<std::int64_t>((static_cast<__int128>(t) * 1'000'000) / kBusHz);
  if (us < 0) {  // not a time the player records; printf's form, kept for any caller
    return out + std::snprintf(out, 40, "%" PRId64 ".%06" PRId64, us / 1'000'000, us % 1'000'000);
  }
  out = std::to_chars(out, out + 20, us / 1'000'000).ptr;
  *out++ = '.';
  std::int64_t frac = us % 1'000'000;
  for (int i = 5; i >= 0; --i, frac /= 10) out[i] = static_cast<char>('0' + frac % 10);
  return out + 6;
}

std::string seconds(Tick t) {
  char buf[40];
  return std::string(buf, formatSeconds(buf, t));
}

// One line of hashes.txt or timeline.csv, built in place: a play writes two per vsync, and
// strings joined with + (a temporary and an allocation per field) were 5 % of a 256x256 play.
class LineBuilder {
 public:
  LineBuilder& operator<<(std::int64_t v) {
    p_ = std::to_chars(p_, end(), v).ptr;
    return *this;
  }
  LineBuilder& operator<<(char c) {
    *p_++ = c;
    return *this;
  }
  LineBuilder& operator<<(bool b) { return *this << (b ? '1' : '0'); }
  LineBuilder& seconds(Tick t) {
    p_ = formatSeconds(p_, t);
    return *this;
  }
  LineBuilder& hash(std::uint64_t h) {
    static const char* kDigits = "0123456789abcdef";
    for (int i = 15; i >= 0; --i, h >>= 4) p_[i] = kDigits[h & 15];
    p_ += 16;
    return *this;
  }
  std::string str() const { return std::string(buf_, static_cast<std::size_t>(p_ - buf_)); }

 private:
  char* end() { return buf_ + sizeof buf_; }
  char buf_[512];  // 17 fields of at most 40 chars
  char* p_ = buf_;
};

// A ratio as a JSON number with 4 decimals, formatted from integers (identical everywhere).
json::Value share(Tick part, Tick whole) {
  if (whole <= 0) return 0;
  const std::int64_t permyriad = static_cast<std::int64_t>((static_cast<__int128>(part) * 10'000) / whole);
  return json::Value::decimal(std::to_string(permyriad / 10'000) + "." +
                              std::string(4 - std::to_string(permyriad % 10'000).size(), '0') +
                              std::to_string(permyriad % 10'000));
}

json::Value extreme(const Extreme& e) {
  return json::object(
      {{"max", e.value}, {"vsync", e.vsync}, {"time_s", json::Value::decimal(e.vsync < 0 ? "0" : seconds(e.at))}});
}

json::Value presenterJson(const gs::PresenterCounters& c) {
  return json::object({{"vsyncs", c.vsyncs},
                       {"frames_shown", c.framesShown},
                       {"frames_on_time", c.framesShown - c.framesLate},
                       {"frames_late", c.framesLate},
                       {"frames_dropped", c.framesDropped},
                       {"frames_caught_up", c.framesCaughtUp},
                       {"catch_up_vsyncs", c.catchUpVsyncs},
                       {"behind_vsyncs", c.behindVsyncs},
                       {"missed_vsyncs", c.missedVsyncs},
                       {"snaps", c.snaps},
                       {"loop_wraps", c.loopWraps},
                       {"branches", c.branches},
                       {"upload_bytes", c.uploadBytes},
                       {"upload_transfers", c.uploadTransfers},
                       {"upload_setup_qwords", c.uploadSetupQwords},
                       {"gs_busy_ticks", c.gsBusy},
                       {"slip_ticks", c.slip}});
}

}  // namespace

std::string hashesLine(const VsyncRow& row) {
  LineBuilder b;
  b << std::int64_t{row.vsync} << ' ';
  b.seconds(row.at) << ' ';
  b.hash(row.hash) << '\n';
  return b.str();
}

RunHealth runHealth(const gs::PresenterCounters& lightmap, const RunTotals& totals) {
  RunHealth h;
  h.stuckFor = totals.endsBehind ? totals.lastVsyncAt - totals.lastProgressAt : 0;
  if (h.stuckFor >= kStuckAfter) h.verdict = lightmap.framesShown == 0 ? "starved" : "stuck";
  return h;
}

std::string healthWarning(const RunHealth& h) {
  if (h.verdict == "ok") return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", toSeconds(h.stuckFor));
  const std::string what = h.verdict == "starved" ? "no frame was ever shown" : "the display stopped";
  return "warning: " + h.verdict + " run: " + what +
         ": the lightmap was behind schedule with no new frame for the last " + buf +
         " s of the run (a deadlocked ring, a drive that never delivers, or a stall still under way; "
         "docs/player.md, \"Stuck and starved runs\")";
}

std::string timelineHeader() {
  return "vsync,time_s,hash,due_seq,target_seq,variant,fix,pop,behind,catch_up,snapped,sky_target_seq,sky_pop,lag,"
         "sky_lag,ring_banks,gs_busy_ticks\n";
}

std::string timelineLine(const VsyncRow& r) {
  const gs::VsyncRecord& l = r.lightmap;
  LineBuilder b;
  b << std::int64_t{r.vsync} << ',';
  b.seconds(r.at) << ',';
  b.hash(r.hash) << ',' << std::int64_t{l.dueSeq} << ',' << std::int64_t{l.targetSeq} << ',' << std::int64_t{l.variant}
                 << ',' << std::int64_t{l.fix} << ',' << std::int64_t{l.pop} << ',' << l.behind << ',' << l.catchUp
                 << ',' << l.snapped << ',';
  if (r.sky) {
    b << std::int64_t{r.sky->targetSeq} << ',' << std::int64_t{r.sky->pop};
  } else {
    b << std::int64_t{-1} << ',' << std::int64_t{0};
  }
  b << ',' << std::int64_t{r.lag} << ',' << std::int64_t{r.skyLag} << ',' << std::int64_t{r.ringBanks} << ','
    << std::int64_t{l.gsBusy + (r.sky ? r.sky->gsBusy : 0)} << '\n';
  return b.str();
}

void writeStatsJson(const Player& player, std::ostream& out, const json::Value* run) {
  const Pipeline& p = player.pipeline();
  const Tick elapsed = player.now();
  const RunTotals& t = player.totals();
  const auto& lmc = const_cast<Pipeline&>(p).lightmap().counters();
  const gs::Presenter* sky = const_cast<Pipeline&>(p).sky();
  const Tick gsBusy = lmc.gsBusy + (sky ? sky->counters().gsBusy : 0);
  const iop::DriveStats& ds = p.drive().stats();
  const iop::RingStats& rs = p.ring().stats();
  const ee::DemuxCounters& dm = p.demux().counters();
  const streams::DemuxStats& rd = p.demux().reader().stats();
  const ee::DecodeCounters& dc = p.decode();
  const PlayerOptions& o = player.options();

  json::Value busy = json::object({{"sif", share(p.sif().busyTime(), elapsed)},
                                   {"demux", share(dm.busy, elapsed)},
                                   {"ipu", share(dc.busy, elapsed)},
                                   {"gs", share(gsBusy, elapsed)}});
  busy["drive"] = share(p.drive().busyTime(elapsed), elapsed);
  std::int64_t stalls = 0;
  for (const iop::Fault& f : o.faults.faults) stalls += f.kind == iop::Fault::Kind::Stall ? 1 : 0;

  json::Value hist = json::Value::array();
  for (std::int64_t v : t.ringHistogram) hist.push(v);
  const std::int64_t bank = p.ring().bankSectors();
  json::Value ring = json::object({{"bank_sectors", bank},
                                   {"banks_min", t.ringMin < 0 ? 0 : t.ringMin},
                                   {"banks_mean", share(t.ringSum, t.vsyncs)},
                                   {"banks_max", t.ringMax},
                                   {"histogram_banks", hist},
                                   {"underruns", rs.underruns},
                                   {"startup_polls", rs.startupPolls},
                                   {"seek_polls", rs.seekPolls},
                                   {"playback_underruns", rs.playbackUnderruns()},
                                   {"full_polls", rs.fullPolls},
                                   {"timeouts", rs.timeouts},
                                   {"errors", rs.errors},
                                   {"bank_reads", rs.bankReads}});

  json::Value j;
  if (run != nullptr) j["run"] = *run;
  j["simulated_s"] = json::Value::decimal(seconds(elapsed));
  j["simulated_ticks"] = elapsed;
  j["seed"] = o.seed;
  j["reference_pipeline"] = player.hasReference();
  j["busy_share"] = busy;
  const RunHealth health = runHealth(lmc, t);
  j["health"] = json::object({{"verdict", health.verdict},
                              {"stuck_s", json::Value::decimal(seconds(health.stuckFor))},
                              {"stuck_after_s", json::Value::decimal(seconds(kStuckAfter))}});
  j["ring"] = ring;
  j["drive"] = json::object(
      {{"commands", ds.commands},
       {"sectors_read", ds.sectorsRead},
       {"buffered_hits", ds.bufferedHits},
       {"retries", ds.retries},
       {"errors", ds.errors},
       {"spin_ups", ds.spinUps},
       {"stalls_planned", stalls},
       {"stalled_ticks", ds.stalled},
       {"seeks", json::object({{"contiguous", ds.seeks[1]}, {"fast", ds.seeks[2]}, {"full", ds.seeks[3]}})}});
  j["demux"] = json::object({{"reads", dm.reads},
                             {"empty_reads", dm.emptyReads},
                             {"read_errors", dm.readErrors},
                             {"sectors", dm.sectors},
                             {"bytes", dm.bytes},
                             {"seeks", dm.seeks},
                             {"loop_seeks", dm.loopSeeks},
                             {"pictures_loaded", dm.picturesLoaded},
                             {"pictures_ignored", dm.picturesIgnored},
                             {"pictures_over_buffer_depth", dm.overDepth},
                             {"pictures_over_budget", dm.overBudget}});
  j["damage"] = json::object({{"stream_errors", dm.streamErrors},
                              {"bad_sectors", rd.badSectors},
                              {"pictures_dropped_by_reader", rd.droppedPictures},
                              {"pictures_damaged", dm.picturesDamaged},
                              {"pictures_unidentified", dm.picturesUnidentified},
                              {"frames_lost", dm.framesLost},
                              {"concealed_macroblocks", dc.concealedMacroblocks},
                              {"pictures_with_decode_issues", dc.picturesWithIssues},
                              {"undecodable_pictures", dc.undecodable}});
  j["frames"] = json::object({{"lightmap", presenterJson(lmc)}});
  if (sky) j["frames"]["sky"] = presenterJson(sky->counters());
  j["pop"] = json::object({{"lightmap", extreme(t.pop)}, {"sky", extreme(t.skyPop)}});
  j["lag"] = json::object({{"lightmap", extreme(t.lag)}, {"sky", extreme(t.skyLag)}});
  const std::int64_t lmPics = dc.picturesPerStream[0];
  const std::int64_t skyPics = dc.picturesPerStream[1];
  j["cost_per_frame"] = json::object(
      {{"decode_lightmap_ticks_mean", lmPics ? dc.perStream[0] / lmPics : 0},
       {"decode_sky_ticks_mean", skyPics ? dc.perStream[1] / skyPics : 0},
       {"decode_ticks_max", dc.maxPerPicture},
       {"gs_ticks_per_vsync_mean", lmc.vsyncs ? gsBusy / lmc.vsyncs : 0},
       {"gs_ticks_per_new_frame_mean", lmc.framesShown ? gsBusy / std::max<std::int64_t>(1, lmc.framesShown) : 0},
       // Time a presenter waited for the GS while the other one drew (they share one GS).
       {"gs_wait_ticks_per_vsync_mean", lmc.vsyncs ? p.gsUnit().waited() / lmc.vsyncs : 0}});
  j["sustained_bytes_per_s"] =
      elapsed > 0 ? static_cast<std::int64_t>((static_cast<__int128>(dm.bytes) * kBusHz) / elapsed) : std::int64_t{0};
  j["decoded_pictures"] = dc.pictures;
  j["idec_commands"] = dc.idecCommands;  // one per slice: the EE restarts IDEC at each slice start code
  if (dc.commands.bdec > 0) {
    // P and B pictures (the BDEC flow): the EE's busy share and every IPU command by kind.
    j["busy_share"]["ee"] = share(dc.eeBusy, elapsed);
    const ipu::IpuCommandCounts& c = dc.commands;
    j["ipu_commands"] = json::object({{"bclr", c.bclr},
                                      {"idec", c.idec},
                                      {"bdec", c.bdec},
                                      {"vdec", c.vdec},
                                      {"fdec", c.fdec},
                                      {"setiq", c.setiq},
                                      {"setvq", c.setvq},
                                      {"csc", c.csc}});
  }
  if (dc.bdecPictures > 0) {
    // Streams with P and B pictures: what decode order and damage cost beyond the frames shown.
    j["damage"]["pictures_with_broken_reference"] = dc.brokenReferencePictures;
    j["gop"] = json::object({{"pictures_bdec", dc.bdecPictures},
                             {"pictures_for_reference_only", dc.picturesForReference},
                             {"pictures_loaded_for_reference_only", dm.picturesForReference}});
  }
  // Zero unless gs.upload_strategy = ee-reorder.
  j["ee_reorder"] = json::object({{"qwords", dc.reorderedQwords}, {"busy_ticks", dc.reorderBusy}});
  j["vsyncs_recorded"] = t.vsyncs;
  out << j.dump(2) << "\n";
}

std::string playSummary(const Player& player, const std::string& disc, double wall, double cpu, std::int64_t images) {
  const Pipeline& p = player.pipeline();
  const gs::PresenterCounters& c = p.lightmap().counters();
  const RunTotals& tot = player.totals();
  const double seconds = toSeconds(player.duration());
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(1);
  s << "played " << seconds << " s of " << disc << " (" << tot.vsyncs << " vsyncs) in " << std::setprecision(2) << wall
    << " s of host time (" << std::setprecision(1) << seconds / std::max(wall, 1e-9) << "x real time), "
    << std::setprecision(2) << cpu << " s of CPU time (" << std::setprecision(1) << seconds / std::max(cpu, 1e-9)
    << "x real time)\n"
    << "  frames: " << c.framesShown << " shown, " << c.framesLate << " late, " << c.framesDropped << " dropped, "
    << c.framesCaughtUp << " caught up; " << c.loopWraps << " loop wrap(s), " << c.branches << " branch(es)\n"
    << "  pop max " << tot.pop.value << " at " << toSeconds(tot.pop.at) << " s; lag max " << tot.lag.value;
  if (tot.lag.vsync >= 0) s << " at " << toSeconds(tot.lag.at) << " s";
  s << (player.hasReference() ? " (against a fault-free reference run)" : " (no faults: no reference needed)")
    << "\n  ring underruns " << p.ring().stats().underruns << " (" << p.ring().stats().startupPolls
    << " while the stream started, " << p.ring().stats().seekPolls << " after seeks), drive retries "
    << p.drive().stats().retries << ", damaged/lost frames "
    << p.demux().counters().picturesDamaged + p.demux().counters().framesLost << ", images written " << images << "\n";
  if (player.hasReference() && tot.lag.value == 0 && c.framesLate == 0 && c.framesDropped == 0) {
    // A stall test whose stall does nothing is easy to write (the ring and the EE's buffers can hold
    // the whole stream): say so rather than let it pass for a survived fault.
    s << "  the faults changed nothing on screen: no frame late or dropped, lag 0 against the fault-free run"
         " (a stall shows only when it outlasts what the ring and the EE's buffers hold; docs/fault-plans.md)\n";
  }
  return s.str();
}

}  // namespace vbim::player
