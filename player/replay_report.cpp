#include "player/replay_report.hpp"

#include <charconv>
#include <fstream>
#include <iterator>
#include <sstream>

#include "player/frame_hash.hpp"
#include "player/report.hpp"
#include "runtime/error.hpp"

namespace vbim::player {

ExpectedHashes readExpectedHashes(const std::filesystem::path& path) {
  ExpectedHashes e;
  const std::filesystem::path file = std::filesystem::is_directory(path) ? path / "hashes.txt" : path;
  e.origin = file.string();
  std::ifstream f(file, std::ios::binary);
  if (!f) throw ConfigError(e.origin + ": cannot open (expected a run directory or a hashes.txt)");
  const std::string text(std::istreambuf_iterator<char>(f), {});
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto bad = [&](const std::string& what) {
      return ConfigError(e.origin + ":" + std::to_string(n) + ": " + what +
                         " (expected '<vsync> <seconds> <16 hex digits>', one line per vsync from 0)");
    };
    std::istringstream fields(line);
    std::string vsync, time, hash, extra;
    if (!(fields >> vsync >> time >> hash) || (fields >> extra)) throw bad("'" + line + "'");
    const std::string want = std::to_string(e.hashes.size());
    if (vsync != want) throw bad("vsync '" + vsync + "' where vsync " + want + " belongs");
    std::uint64_t h = 0;
    const auto [end, ec] = std::from_chars(hash.data(), hash.data() + hash.size(), h, 16);
    if (hash.size() != 16 || ec != std::errc() || end != hash.data() + hash.size()) throw bad("hash '" + hash + "'");
    e.hashes.push_back(h);
  }
  if (e.hashes.empty()) throw ConfigError(e.origin + ": no vsyncs (expected one line per vsync from 0)");
  return e;
}

namespace {

// The target's arrival vsync, due vsync and lateness (-1, -1, -1 without a target).
struct Origin {
  std::int64_t arrived = -1;
  std::int64_t due = -1;
  std::int64_t late = -1;
  int line = 0;
};

Origin originOf(const Replay& replay, bool sky, const gs::VsyncRecord& r) {
  Origin o;
  if (r.targetSeq < 0) return o;
  o.due = replay.dueVsync(r.targetSeq);
  if (const ReplayArrival* a = replay.arrivalOf(sky, r.variant, r.targetSeq)) {
    o.arrived = a->vsync;
    o.line = a->line;
    o.late = std::max<std::int64_t>(0, a->vsync - o.due);
  }
  return o;
}

}  // namespace

std::string replayTimelineHeader() {
  return "vsync,time_s,hash,due_seq,target_seq,variant,fix,pop,behind,catch_up,snapped,sky_target_seq,sky_pop,"
         "gs_busy_ticks,target_arrived_vsync,target_due_vsync,target_late_vsyncs,sky_target_arrived_vsync,"
         "sky_target_late_vsyncs\n";
}

std::string replayTimelineLine(const VsyncRow& row, const Replay& replay) {
  // time and hash exactly as hashes.txt writes them: "<vsync> <seconds> <hash>\n".
  std::istringstream h(hashesLine(row));
  std::string vsync, seconds, hash;
  h >> vsync >> seconds >> hash;
  const gs::VsyncRecord& l = row.lightmap;
  const Origin lo = originOf(replay, false, l);
  const auto b = [](bool v) { return v ? "1" : "0"; };
  std::string s = vsync + "," + seconds + "," + hash + "," + std::to_string(l.dueSeq) + "," +
                  std::to_string(l.targetSeq) + "," + std::to_string(l.variant) + "," + std::to_string(l.fix) + "," +
                  std::to_string(l.pop) + "," + b(l.behind) + "," + b(l.catchUp) + "," + b(l.snapped) + ",";
  s += row.sky ? std::to_string(row.sky->targetSeq) + "," + std::to_string(row.sky->pop) : std::string("-1,0");
  s += "," + std::to_string(l.gsBusy + (row.sky ? row.sky->gsBusy : 0));
  s += "," + std::to_string(lo.arrived) + "," + std::to_string(lo.due) + "," + std::to_string(lo.late);
  const Origin so = row.sky ? originOf(replay, true, *row.sky) : Origin{};
  s += "," + std::to_string(so.arrived) + "," + std::to_string(so.late) + "\n";
  return s;
}

void ReplayNotes::add(const VsyncRow& row) {
  if (row.lightmap.targetSeq >= 0) shown_.emplace(false, row.lightmap.variant, row.lightmap.targetSeq);
  if (row.sky && row.sky->targetSeq >= 0) shown_.emplace(true, row.sky->variant, row.sky->targetSeq);
  vsyncs_ = row.vsync + 1;
}

std::string ReplayNotes::presenter(const char* name, bool sky, const gs::VsyncRecord& r, std::int64_t vsync) const {
  std::string s = std::string("  ") + name + ": frame " + std::to_string(r.dueSeq) + " due";
  if (r.targetSeq < 0) return s + "; no frame arrived yet: the texture is still all-zero RGBA\n";
  s += ", target frame " + std::to_string(r.targetSeq) + " (variant " + std::to_string(r.variant) + ", FIX " +
       std::to_string(r.fix) + (r.snapped ? ", copied in" : "") + ")";
  const Origin o = originOf(replay_, sky, r);
  if (o.arrived >= 0) {
    s += ", arrived at vsync " + std::to_string(o.arrived) + " (" + origin_ + ":" + std::to_string(o.line) +
         "), due at vsync " + std::to_string(o.due) +
         (o.late > 0 ? ": " + std::to_string(o.late) + " vsyncs late" : ": on time");
  }
  if (r.behind) {
    const ReplayArrival* d = replay_.arrivalOf(sky, r.variant, r.dueSeq);
    s += "; behind: frame " + std::to_string(r.dueSeq) + " " +
         (d != nullptr && d->vsync > vsync
              ? "arrives at vsync " + std::to_string(d->vsync) + " (" + origin_ + ":" + std::to_string(d->line) + ")"
              : std::string("has not arrived"));
  }
  return s + "\n";
}

std::string ReplayNotes::describe(const VsyncRow& row) const {
  std::string s = presenter("lightmap", false, row.lightmap, row.vsync);
  if (row.sky) s += presenter("sky", true, *row.sky, row.vsync);
  return s;
}

std::vector<std::string> ReplayNotes::lateOrUnshown() const {
  std::vector<std::string> out;
  for (const ReplayArrival& a : log_.arrivals) {
    if (a.vsync >= vsyncs_) continue;  // after the replay's end
    const std::int64_t due = replay_.dueVsync(a.seq);
    const bool late = a.vsync > due;
    const bool unshown = due < vsyncs_ && shown_.count({a.sky, a.variant, a.seq}) == 0;
    if (!late && !unshown) continue;
    std::string s = origin_ + ":" + std::to_string(a.line) + ": " + arrivalStream(a) + " frame " +
                    std::to_string(a.seq) + " arrived at vsync " + std::to_string(a.vsync) + ", due at vsync " +
                    std::to_string(due);
    if (late) s += ": " + std::to_string(a.vsync - due) + " vsyncs late";
    if (unshown) s += "; never shown (a newer frame was due before it arrived)";
    out.push_back(s);
  }
  return out;
}

std::string hashDifference(const ExpectedHashes& e, const VsyncRow& row, const ReplayNotes& notes) {
  const auto v = static_cast<std::size_t>(row.vsync);
  if (v < e.hashes.size() && e.hashes[v] == row.hash) return "";
  std::istringstream line(hashesLine(row));
  std::string vsync, seconds;
  line >> vsync >> seconds;
  std::string s =
      "first difference at vsync " + vsync + " (" + seconds + " s): replay " + hashHex(row.hash) + ", " + e.origin +
      (v < e.hashes.size() ? ":" + std::to_string(v + 1) + " " + hashHex(e.hashes[v]) : " has no line for it") + "\n";
  return s + notes.describe(row);
}

}  // namespace vbim::player
