#include "config/fault_plan_toml.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "config/fault_template.hpp"
#include "config/toml_document.hpp"
#include "iop/sector_source.hpp"

namespace vbim::config {

using iop::Fault;
using iop::FaultPlan;
using iop::parseDuration;
using iop::SectorSource;
using iop::toString;

namespace {

struct Kind {
  const char* name;
  Fault::Kind kind;
  std::vector<std::string> required;
  std::vector<std::string> optional;
};

const std::vector<Kind>& kinds() {
  static const std::vector<Kind> k = {
      {"stall", Fault::Kind::Stall, {"at", "duration"}, {}},
      {"read_error", Fault::Kind::ReadError, {"lba", "attempts"}, {"from"}},
      {"seek_away", Fault::Kind::SeekAway, {"at", "sectors"}, {"lba", "file"}},
      {"contention", Fault::Kind::Contention, {"from", "duration", "share"}, {"period", "lba", "file"}},
      {"random_stall", Fault::Kind::RandomStall, {"from", "duration", "mean_interval", "stall"}, {}},
      {"random_error", Fault::Kind::RandomError, {"from", "duration", "per_million"}, {"attempts"}},
  };
  return k;
}

class Reader {
 public:
  Reader(const std::string& origin, const toml::table& t, int line, std::string kind, const SectorSource* disc,
         std::vector<FaultRange>* ranges = nullptr, std::size_t faultIndex = 0)
      : origin_(origin),
        t_(t),
        line_(line),
        kind_(std::move(kind)),
        disc_(disc),
        ranges_(ranges),
        faultIndex_(faultIndex) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    int line = line_;
    if (const toml::node* n = t_.get(field)) line = static_cast<int>(n->source().begin.line);
    throw ConfigError(origin_ + ":" + std::to_string(line) + ": fault '" + kind_ + "'" +
                      (field.empty() ? "" : ", field '" + field + "'") + ": " + what);
  }
  bool has(const std::string& f) const { return t_.get(f) != nullptr; }

  // A time; in a template, `{ min = "1s", max = "4s" }` is a range: both ends are checked, the
  // minimum is returned and the range recorded for the draws.
  Tick time(const std::string& f, bool positive) const {
    const toml::node* n = t_.get(f);
    if (n == nullptr) fail(f, "missing (expected a time such as \"800ms\")");
    if (const toml::table* range = rangeOf(f, n)) {
      const Tick lo = timeValue(f, range->get("min"), positive);
      const Tick hi = timeValue(f, range->get("max"), positive);
      return record(f, lo, hi, true);
    }
    return timeValue(f, n, positive);
  }
  Tick timeValue(const std::string& f, const toml::node* n, bool positive) const {
    const auto s = n->value<std::string>();
    if (!s) fail(f, "expected a time as a string with a unit, such as \"12.5s\", \"800ms\" or \"250us\"");
    Tick t = 0;
    try {
      t = parseDuration(*s);
    } catch (const std::invalid_argument& e) {
      fail(f, "'" + *s + "' is not a valid time: " + e.what());
    }
    if (positive && t <= 0) fail(f, "'" + *s + "' must be longer than zero");
    return t;
  }
  std::int64_t integer(const std::string& f, std::int64_t min, std::int64_t max) const {
    const toml::node* n = t_.get(f);
    if (n == nullptr) fail(f, "missing");
    if (const toml::table* range = rangeOf(f, n)) {
      const std::int64_t lo = integerValue(f, range->get("min"), min, max);
      const std::int64_t hi = integerValue(f, range->get("max"), min, max);
      return record(f, lo, hi, false);
    }
    return integerValue(f, n, min, max);
  }
  std::int64_t integerValue(const std::string& f, const toml::node* n, std::int64_t min, std::int64_t max) const {
    if (!n->is_integer()) fail(f, "expected an integer");
    const std::int64_t v = *n->value<std::int64_t>();
    if (v < min || v > max) {
      fail(f, std::to_string(v) + " is outside the allowed range [" + std::to_string(min) + ", " + std::to_string(max) +
                  "]");
    }
    return v;
  }
  // `lba = N` or `file = "path"` (resolved on the disc like sceCdSearchFile).
  std::int64_t location(bool required, std::int64_t* fileSectors = nullptr) const {
    if (has("lba") && has("file")) fail("file", "give either lba or file, not both");
    if (has("file")) {
      const auto s = t_.get("file")->value<std::string>();
      if (!s) fail("file", "expected a path string");
      if (disc_ == nullptr) fail("file", "a file name needs a disc to look it up in; give lba instead");
      const auto f = disc_->find(*s);
      if (!f) fail("file", "no file '" + *s + "' on " + disc_->describe());
      if (fileSectors != nullptr) *fileSectors = f->sectors();
      return f->lba;
    }
    if (!has("lba")) {
      if (required) fail("lba", "missing (give lba or file)");
      return -1;
    }
    const std::int64_t max = disc_ != nullptr ? disc_->sectorCount() - 1 : (std::int64_t{1} << 40);
    return integer("lba", 0, max);
  }

 private:
  // The {min, max} table of a ranged field (templates only), else null.
  const toml::table* rangeOf(const std::string& f, const toml::node* n) const {
    const toml::table* range = n->as_table();
    if (range == nullptr) return nullptr;
    if (ranges_ == nullptr) fail(f, "a range { min, max } is allowed only in a sweep plan's fault template");
    for (const auto& [k, v] : *range) {
      if (k.str() != "min" && k.str() != "max") fail(f, "a range takes only min and max");
    }
    if (range->get("min") == nullptr || range->get("max") == nullptr) fail(f, "a range needs both min and max");
    return range;
  }
  std::int64_t record(const std::string& f, std::int64_t lo, std::int64_t hi, bool time) const {
    if (hi < lo) fail(f, "the range's max is below its min");
    const int line = static_cast<int>(t_.get(f)->source().begin.line);
    ranges_->push_back(FaultRange{faultIndex_, f, lo, hi, time, line});
    return lo;
  }

  const std::string& origin_;
  const toml::table& t_;
  int line_;
  std::string kind_;
  const SectorSource* disc_;
  std::vector<FaultRange>* ranges_;
  std::size_t faultIndex_;
};

std::string fmtTime(Tick t) {
  char buf[40];
  formatMicros(t, buf, sizeof buf);
  return std::string(buf) + " us";
}

void rejectOverlaps(const std::string& origin, const std::vector<Fault>& faults, Fault::Kind kind) {
  std::vector<const Fault*> list;
  for (const Fault& f : faults) {
    if (f.kind == kind) list.push_back(&f);
  }
  std::sort(list.begin(), list.end(), [](const Fault* a, const Fault* b) { return a->at < b->at; });
  for (std::size_t i = 1; i < list.size(); ++i) {
    const Fault& a = *list[i - 1];
    const Fault& b = *list[i];
    if (b.at < a.at + a.duration) {
      throw ConfigError(origin + ":" + std::to_string(b.line) + ": fault '" + toString(kind) + "' starting at " +
                        fmtTime(b.at) + " overlaps the one at line " + std::to_string(a.line) + " (" + fmtTime(a.at) +
                        " to " + fmtTime(a.at + a.duration) + "); merge them into one entry or move one");
    }
  }
}

}  // namespace

iop::FaultPlan parseFaultPlan(std::string_view text, const std::string& origin, const iop::SectorSource* disc) {
  const toml::table doc = parseTomlDocument(text, origin);
  for (const auto& [k, v] : doc) {
    if (k.str() != "fault") {
      throw ConfigError(origin + ":" + std::to_string(v.source().begin.line) + ": unknown key '" +
                        std::string(k.str()) + "': a fault plan holds only [[fault]] tables");
    }
  }
  return parseFaultArray(doc.get("fault"), origin, disc, nullptr);
}

void checkDrawnFaultPlan(const iop::FaultPlan& plan, const std::string& origin) {
  for (const Fault& f : plan.faults) {
    if (f.kind == Fault::Kind::RandomStall && f.stallLength >= f.meanInterval) {
      throw ConfigError(origin + ":" + std::to_string(f.line) +
                        ": fault 'random_stall': the drawn stall is not shorter than the drawn mean_interval");
    }
    if (f.kind == Fault::Kind::Contention && f.period > f.duration) {
      throw ConfigError(origin + ":" + std::to_string(f.line) +
                        ": fault 'contention': the drawn period is longer than the drawn duration");
    }
    if (f.kind == Fault::Kind::Contention && f.period < iop::kMinFaultInterval) {
      throw ConfigError(origin + ":" + std::to_string(f.line) +
                        ": fault 'contention': the drawn period is shorter than 1ms, the least it may be");
    }
    if (f.kind == Fault::Kind::RandomStall && f.meanInterval < iop::kMinFaultInterval) {
      throw ConfigError(origin + ":" + std::to_string(f.line) +
                        ": fault 'random_stall': the drawn mean_interval is shorter than 1ms, the least it may be");
    }
  }
  rejectOverlaps(origin, plan.faults, Fault::Kind::Stall);
  rejectOverlaps(origin, plan.faults, Fault::Kind::Contention);
  rejectOverlaps(origin, plan.faults, Fault::Kind::RandomStall);
  rejectOverlaps(origin, plan.faults, Fault::Kind::RandomError);
}

iop::FaultPlan parseFaultArray(const toml::node* node, const std::string& origin, const iop::SectorSource* disc,
                               std::vector<FaultRange>* ranges) {
  FaultPlan plan;
  plan.origin = origin;
  if (node == nullptr) return plan;  // an empty plan: no faults
  const toml::array* arr = node->as_array();
  if (arr == nullptr) {
    throw ConfigError(origin + ":" + std::to_string(node->source().begin.line) +
                      ": 'fault' must be an array of tables, written [[fault]]");
  }
  std::set<std::int64_t> errorLbas;
  std::map<std::int64_t, int> errorLines;
  for (const toml::node& el : *arr) {
    const int line = static_cast<int>(el.source().begin.line);
    const toml::table* t = el.as_table();
    if (t == nullptr) throw ConfigError(origin + ":" + std::to_string(line) + ": each fault must be a [[fault]] table");
    const toml::node* kn = t->get("kind");
    if (kn == nullptr || !kn->value<std::string>()) {
      throw ConfigError(origin + ":" + std::to_string(line) +
                        ": fault without a kind (expected kind = \"stall\", \"read_error\", \"seek_away\", "
                        "\"contention\", \"random_stall\" or \"random_error\")");
    }
    const std::string kindName = *kn->value<std::string>();
    const Kind* kind = nullptr;
    for (const Kind& k : kinds()) {
      if (kindName == k.name) kind = &k;
    }
    if (kind == nullptr) {
      throw ConfigError(origin + ":" + std::to_string(kn->source().begin.line) + ": unknown fault kind '" + kindName +
                        "' (expected stall, read_error, seek_away, contention, random_stall or random_error)");
    }
    Reader r(origin, *t, line, kindName, disc, ranges, plan.faults.size());
    for (const auto& [fk, fv] : *t) {
      const std::string field(fk.str());
      if (field == "kind") continue;
      const bool known = std::find(kind->required.begin(), kind->required.end(), field) != kind->required.end() ||
                         std::find(kind->optional.begin(), kind->optional.end(), field) != kind->optional.end();
      if (!known) {
        std::string list;
        for (const auto& f : kind->required) list += (list.empty() ? "" : ", ") + f;
        for (const auto& f : kind->optional) list += ", " + f + " (optional)";
        r.fail(field, "unknown field (a " + kindName + " takes " + list + ")");
      }
    }
    Fault f;
    f.kind = kind->kind;
    f.line = line;
    switch (f.kind) {
      case Fault::Kind::Stall:
        f.at = r.time("at", false);
        f.duration = r.time("duration", true);
        break;
      case Fault::Kind::ReadError:
        f.lba = r.location(true);
        f.attempts = r.integer("attempts", 1, 1'000'000);
        f.at = r.has("from") ? r.time("from", false) : 0;
        if (errorLbas.count(f.lba) != 0) {
          r.fail("lba", "LBA " + std::to_string(f.lba) + " already has a read_error at line " +
                            std::to_string(errorLines[f.lba]) + "; give one entry with the total attempts");
        }
        errorLbas.insert(f.lba);
        errorLines[f.lba] = line;
        break;
      case Fault::Kind::SeekAway: {
        f.at = r.time("at", false);
        std::int64_t fileSectors = 0;
        f.lba = r.location(true, &fileSectors);
        f.sectors = r.integer("sectors", 1, 1'000'000);
        if (disc != nullptr && f.lba + f.sectors > disc->sectorCount()) {
          r.fail("sectors", std::to_string(f.sectors) + " sectors from LBA " + std::to_string(f.lba) +
                                " run past the end of the disc (" + std::to_string(disc->sectorCount()) + " sectors)");
        }
        break;
      }
      case Fault::Kind::Contention:
        f.at = r.time("from", false);
        f.duration = r.time("duration", true);
        f.share = r.integer("share", 1, 99);
        f.period = r.has("period") ? r.time("period", true) : fromMs(100);
        f.lba = r.location(false);
        if (f.period < iop::kMinFaultInterval) {
          r.fail("period", "is shorter than 1ms, the least a contention period may be (docs/fault-plans.md)");
        }
        if (f.period > f.duration) r.fail("period", "is longer than the contention's duration");
        break;
      case Fault::Kind::RandomStall:
        f.at = r.time("from", false);
        f.duration = r.time("duration", true);
        f.meanInterval = r.time("mean_interval", true);
        f.stallLength = r.time("stall", true);
        if (f.meanInterval < iop::kMinFaultInterval) {
          r.fail("mean_interval", "is shorter than 1ms, the least a mean interval may be (docs/fault-plans.md)");
        }
        if (f.stallLength >= f.meanInterval) {
          r.fail("stall", "must be shorter than mean_interval, or the drive would never run");
        }
        break;
      case Fault::Kind::RandomError:
        f.at = r.time("from", false);
        f.duration = r.time("duration", true);
        f.perMillion = r.integer("per_million", 1, 1'000'000);
        f.attempts = r.has("attempts") ? r.integer("attempts", 1, 1'000'000) : 1;
        break;
    }
    plan.faults.push_back(f);
  }
  rejectOverlaps(origin, plan.faults, Fault::Kind::Stall);
  rejectOverlaps(origin, plan.faults, Fault::Kind::Contention);
  rejectOverlaps(origin, plan.faults, Fault::Kind::RandomStall);
  rejectOverlaps(origin, plan.faults, Fault::Kind::RandomError);
  return plan;
}

iop::FaultPlan loadFaultPlan(const std::string& path, const iop::SectorSource* disc) {
  return parseFaultPlan(readTomlFile(path, "fault plan"), path, disc);
}

}  // namespace vbim::config
