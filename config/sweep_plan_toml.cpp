#include "config/sweep_plan_toml.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <set>

#include "config/fault_plan_toml.hpp"
#include "config/fault_template.hpp"
#include "config/platform_config_toml.hpp"
#include "config/toml_document.hpp"
#include "gs/params.hpp"
#include "runtime/rng.hpp"

namespace vbim::config {

namespace {

using namespace sweep;

int lineOf(const toml::node& n) {
  return static_cast<int>(n.source().begin.line);
}

// Reads one table of the plan; every message is origin:line: key 'path.key': what was expected.
class Section {
 public:
  Section(const std::string& origin, const toml::table& t, std::string path, const std::set<std::string>& known)
      : origin_(origin), t_(t), path_(std::move(path)) {
    for (const auto& [k, v] : t) {
      if (known.count(std::string(k.str())) == 0) {
        std::string list;
        for (const auto& n : known) list += (list.empty() ? "" : ", ") + n;
        fail(&v, std::string(k.str()), "unknown key (expected one of " + list + ")");
      }
    }
  }
  [[noreturn]] void fail(const toml::node* n, const std::string& key, const std::string& what) const {
    const int line = n != nullptr ? lineOf(*n) : lineOf(t_);
    throw ConfigError(origin_ + ":" + std::to_string(line) + ": key '" + name(key) + "': " + what);
  }
  std::string name(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const toml::node* get(const std::string& key) const { return t_.get(key); }

  std::string string(const std::string& key, const std::string& fallback) const {
    const toml::node* n = get(key);
    if (n == nullptr) return fallback;
    const auto v = n->value<std::string>();
    if (!v) fail(n, key, "expected a string");
    return *v;
  }
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t min, std::int64_t max) const {
    const toml::node* n = get(key);
    if (n == nullptr) return fallback;
    if (!n->is_integer()) fail(n, key, "expected an integer");
    const std::int64_t v = *n->value<std::int64_t>();
    if (v < min || v > max) {
      fail(n, key, std::to_string(v) + " is outside [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    }
    return v;
  }
  Tick time(const std::string& key, Tick fallback) const {
    const toml::node* n = get(key);
    if (n == nullptr) return fallback;
    const auto s = n->value<std::string>();
    if (!s) fail(n, key, "expected a time as a string with a unit, such as \"12.5s\" or \"800ms\"");
    Tick t = 0;
    try {
      t = iop::parseDuration(*s);
    } catch (const std::invalid_argument& e) {
      fail(n, key, "'" + *s + "' is not a valid time: " + e.what());
    }
    if (t <= 0) fail(n, key, "'" + *s + "' must be longer than zero");
    return t;
  }
  // An array (absent: empty); each element is handed to `each` with its node.
  template <typename F>
  void array(const std::string& key, F&& each) const {
    const toml::node* n = get(key);
    if (n == nullptr) return;
    const toml::array* a = n->as_array();
    if (a == nullptr) fail(n, key, "expected an array [ ... ]");
    if (a->empty()) fail(n, key, "is empty: leave the key out for the default");
    for (const toml::node& el : *a) each(el);
  }
  const toml::table& table() const { return t_; }

 private:
  const std::string& origin_;
  const toml::table& t_;
  std::string path_;
};

const toml::table* subTable(const Section& parent, const std::string& key) {
  const toml::node* n = parent.get(key);
  if (n == nullptr) return nullptr;
  const toml::table* t = n->as_table();
  if (t == nullptr) parent.fail(n, key, "expected a table [" + parent.name(key) + "]");
  return t;
}

std::string resolve(const std::string& baseDir, const std::string& path) {
  const std::filesystem::path p(path);
  return p.is_absolute() || baseDir.empty() ? path : (std::filesystem::path(baseDir) / p).lexically_normal().string();
}

std::string seconds(Tick t) {
  char b[48];
  std::snprintf(b, sizeof b, "%.6fs", toSeconds(t));
  return b;
}

// The field a range sets on a fault (fault_plan_toml.cpp names them as the plan's keys).
void setField(iop::Fault& f, const std::string& field, std::int64_t v) {
  if (field == "at" || field == "from") f.at = v;
  if (field == "duration") f.duration = v;
  if (field == "lba") f.lba = v;
  if (field == "sectors") f.sectors = v;
  if (field == "attempts") f.attempts = v;
  if (field == "share") f.share = v;
  if (field == "period") f.period = v;
  if (field == "mean_interval") f.meanInterval = v;
  if (field == "stall") f.stallLength = v;
  if (field == "per_million") f.perMillion = v;
}

// One entry of `gops`: { gop = N, b_frames = M, open_gop = true } (the limits of `vbim author`).
StreamSpec readGop(const Section& axes, const std::string& origin, const toml::node& el) {
  const toml::table* t = el.as_table();
  if (t == nullptr) axes.fail(&el, "gops", "expected GOP structures as tables, e.g. { gop = 12, b_frames = 2 }");
  const Section s(origin, *t, "axes.gops", {"gop", "b_frames", "open_gop"});
  if (s.get("gop") == nullptr) s.fail(&el, "gop", "missing: pictures from one I picture to the next (1: intra only)");
  StreamSpec g;
  g.gop = static_cast<int>(s.integer("gop", 1, 1, 1024));         // temporal_reference is 10 bits (13818-2 6.3.9)
  g.bFrames = static_cast<int>(s.integer("b_frames", 0, 0, 16));  // libavcodec's MAX_B_FRAMES
  if (g.bFrames >= g.gop && g.bFrames > 0) {
    s.fail(s.get("b_frames"), "b_frames",
           std::to_string(g.bFrames) + " B pictures need a gop above " + std::to_string(g.bFrames) + " (a GOP of " +
               std::to_string(g.gop) + " has room for " + std::to_string(g.gop - 1) + ")");
  }
  if (const toml::node* n = s.get("open_gop")) {
    if (!n->is_boolean()) s.fail(n, "open_gop", "expected true or false");
    g.openGop = *n->value<bool>();
    if (g.openGop && g.bFrames == 0) s.fail(n, "open_gop", "needs b_frames: only B pictures refer across a GOP header");
  }
  return g;
}

std::string gopSuffix(const StreamSpec& g) {
  return "_g" + std::to_string(g.gop) + (g.bFrames > 0 ? "b" + std::to_string(g.bFrames) : "") +
         (g.openGop ? "open" : "");
}

// `streams`, then the first one re-encoded: at each of `qscales` then `bitrates`, and with `gops`
// at each of those in each GOP structure (quality outer, GOP inner).
void readStreams(const Section& axes, const std::string& origin, const std::string& baseDir, SweepPlanSpec& plan) {
  axes.array("streams", [&](const toml::node& el) {
    const auto s = el.value<std::string>();
    if (!s) axes.fail(&el, "streams", "expected stream file paths (strings)");
    StreamSpec spec;
    spec.label = std::filesystem::path(*s).stem().string();
    spec.path = resolve(baseDir, *s);
    plan.streams.push_back(spec);
  });
  if (plan.streams.empty()) axes.fail(nullptr, "streams", "missing: name at least one stream file");
  const StreamSpec first = plan.streams.front();
  std::vector<StreamSpec> qualities;  // label suffix in `label`
  axes.array("qscales", [&](const toml::node& el) {
    const auto q = el.value<std::int64_t>();
    if (!el.is_integer() || *q < 1 || *q > 31) axes.fail(&el, "qscales", "expected quantisers 1..31");
    StreamSpec s;
    s.label = "_q" + std::to_string(*q);
    s.qscale = static_cast<int>(*q);
    qualities.push_back(s);
  });
  axes.array("bitrates", [&](const toml::node& el) {
    const auto b = el.value<std::int64_t>();
    if (!el.is_integer() || *b < 1 || *b > 9'800'000) axes.fail(&el, "bitrates", "expected bit/s in 1..9800000");
    StreamSpec s;
    s.label = "_" + std::to_string(*b / 1000) + "kbps";
    s.bitrate = *b;
    qualities.push_back(s);
  });
  std::vector<StreamSpec> gops;
  axes.array("gops", [&](const toml::node& el) {
    StreamSpec g = readGop(axes, origin, el);
    for (const StreamSpec& o : gops) {
      if (o.gop == g.gop && o.bFrames == g.bFrames && o.openGop == g.openGop) {
        axes.fail(
            &el, "gops",
            "gop " + std::to_string(g.gop) + " with " + std::to_string(g.bFrames) + " B pictures is listed twice");
      }
    }
    gops.push_back(g);
  });
  if (!gops.empty() && qualities.empty()) {
    axes.fail(axes.get("gops"), "gops",
              "needs qscales or bitrates: the quantisers (or bit rates) each GOP structure is re-encoded at");
  }
  if (gops.empty()) gops.emplace_back();  // intra only, labelled as before GOPs existed
  const bool named = gops.size() > 1 || gops.front().gop != 1 || axes.get("gops") != nullptr;
  for (const StreamSpec& q : qualities) {
    for (const StreamSpec& g : gops) {
      StreamSpec s = g;
      s.label = first.label + q.label + (named ? gopSuffix(g) : "");
      s.path = first.path;
      s.qscale = q.qscale;
      s.bitrate = q.bitrate;
      plan.streams.push_back(s);
    }
  }
}

void readRingsPoliciesSeeds(const Section& axes, SweepPlanSpec& plan) {
  axes.array("rings", [&](const toml::node& el) {
    const auto s = el.value<std::string>();
    RingSize r;
    int used = 0;
    long long banks = 0, sectors = 0;
    const bool ok = s && std::sscanf(s->c_str(), "%lld:%lld%n", &banks, &sectors, &used) == 2 &&
                    static_cast<std::size_t>(used) == s->size() && banks >= 1 && sectors >= banks;
    if (!ok) axes.fail(&el, "rings", "expected \"BANKS:SECTORS\" (ring.bankmax:ring.bufmax_sectors), e.g. \"4:32\"");
    r.bankmax = banks;
    r.bufmax = sectors;
    plan.rings.push_back(r);
  });
  if (plan.rings.empty()) plan.rings.push_back(RingSize{});
  axes.array("policies", [&](const toml::node& el) {
    const auto s = el.value<std::string>();
    const bool ok =
        s && std::find(gs::kCatchupPolicies.begin(), gs::kCatchupPolicies.end(), *s) != gs::kCatchupPolicies.end();
    if (!ok) axes.fail(&el, "policies", "expected blend-through, hard-skip or play-late");
    plan.policies.push_back(*s);
  });
  if (plan.policies.empty()) plan.policies.emplace_back("blend-through");
  axes.array("seeds", [&](const toml::node& el) {
    const auto v = el.value<std::int64_t>();
    if (!el.is_integer() || *v < 0) axes.fail(&el, "seeds", "expected non-negative integers");
    plan.seeds.push_back(static_cast<std::uint64_t>(*v));
  });
  if (plan.seeds.empty()) plan.seeds.push_back(1);
}

// [[axes.platform]] key = "drive.x", values = [...]: the product of all such axes over the base.
void readPlatforms(const Section& axes, const std::string& origin, const player::PlatformConfig& base,
                   SweepPlanSpec& plan) {
  plan.platforms.push_back({{}, base});
  axes.array("platform", [&](const toml::node& el) {
    const toml::table* t = el.as_table();
    if (t == nullptr) axes.fail(&el, "platform", "expected [[axes.platform]] tables");
    const Section s(origin, *t, "axes.platform", {"key", "values"});
    const std::string key = s.string("key", "");
    if (key.empty()) s.fail(nullptr, "key", "missing: the platform-config key to vary, e.g. \"gs.fix\"");
    if (std::find(plan.platformKeys.begin(), plan.platformKeys.end(), key) != plan.platformKeys.end())
      s.fail(s.get("key"), "key", "'" + key + "' is already an axis");
    std::vector<PlatformVariant> next;
    for (const PlatformVariant& v : plan.platforms) {
      s.array("values", [&](const toml::node& value) {
        PlatformVariant w = v;
        ParamTable table;
        player::describeParams(table, w.config);
        applyTomlValue(table, key, value, origin);
        try {
          player::validate(w.config);
        } catch (const ConfigError& e) {
          throw ConfigError(origin + ":" + std::to_string(lineOf(value)) + ": key '" + key + "': " + e.what());
        }
        std::string text;
        if (const auto str = value.value<std::string>()) {
          text = *str;
        } else if (value.is_integer()) {
          text = std::to_string(*value.value<std::int64_t>());
        } else if (value.is_boolean()) {
          text = *value.value<bool>() ? "true" : "false";
        } else {
          char b[32];
          std::snprintf(b, sizeof b, "%.10g", *value.value<double>());
          text = b;
        }
        w.values.emplace_back(key, text);
        next.push_back(std::move(w));
      });
    }
    if (next.empty()) s.fail(nullptr, "values", "missing: the values to sweep");
    plan.platforms = std::move(next);
    plan.platformKeys.push_back(key);
  });
}

// [[faults]]: name, draws, and either plan = "file.toml" or [[faults.fault]] tables with ranges.
void readFaults(const Section& top, const std::string& origin, const std::string& baseDir, std::uint64_t seed,
                SweepPlanSpec& plan) {
  top.array("faults", [&](const toml::node& el) {
    const toml::table* t = el.as_table();
    if (t == nullptr) top.fail(&el, "faults", "expected [[faults]] tables");
    const Section s(origin, *t, "faults", {"name", "draws", "plan", "fault"});
    FaultTemplate ft;
    ft.name = s.string("name", "");
    if (ft.name.empty()) s.fail(nullptr, "name", "missing: a label for the table (e.g. \"random-stalls\")");
    for (const FaultTemplate& other : plan.faults) {
      if (other.name == ft.name) s.fail(s.get("name"), "name", "'" + ft.name + "' names another template too");
    }
    const auto draws = static_cast<std::size_t>(s.integer("draws", 1, 1, 1'000'000));
    iop::FaultPlan base;
    std::vector<FaultRange> ranges;
    if (s.get("plan") != nullptr) {
      if (s.get("fault") != nullptr) s.fail(s.get("fault"), "fault", "give either plan or [[faults.fault]]");
      base = loadFaultPlan(resolve(baseDir, s.string("plan", "")));
    } else {
      base = parseFaultArray(s.get("fault"), origin, nullptr, &ranges);
    }
    for (std::size_t d = 0; d < draws; ++d) {
      // Each draw has its own stream: named by template and draw, independent of the others.
      Rng rng = Rng(seed).fork("faults/" + ft.name).fork(std::to_string(d));
      FaultDraw fd;
      fd.plan = base;
      for (const FaultRange& r : ranges) {
        const std::int64_t v = r.lo + static_cast<std::int64_t>(rng.below(static_cast<std::uint64_t>(r.hi - r.lo) + 1));
        iop::Fault& f = fd.plan.faults[r.fault];
        setField(f, r.field, v);
        if (!fd.drawn.empty()) fd.drawn += "; ";
        fd.drawn += std::string(iop::toString(f.kind)) + "[" + std::to_string(r.fault + 1) + "]." + r.field + "=" +
                    (r.time ? seconds(v) : std::to_string(v));
      }
      try {
        checkDrawnFaultPlan(fd.plan, origin);
      } catch (const ConfigError& e) {
        throw ConfigError(std::string(e.what()) + " (template '" + ft.name + "', draw " + std::to_string(d) +
                          ": narrow the ranges)");
      }
      ft.draws.push_back(std::move(fd));
    }
    plan.faults.push_back(std::move(ft));
  });
  if (plan.faults.empty()) plan.faults.push_back({"none", {FaultDraw{}}});
}

const std::array<std::pair<const char*, Measure>, 9> kMeasures{{{"frames_late", Measure::FramesLate},
                                                                {"frames_dropped", Measure::FramesDropped},
                                                                {"frames_caught_up", Measure::FramesCaughtUp},
                                                                {"pop_max", Measure::PopMax},
                                                                {"lag_max", Measure::LagMax},
                                                                {"ring_occupancy", Measure::RingOccupancy},
                                                                {"survivable_stall", Measure::SurvivableStall},
                                                                {"coding", Measure::Coding},
                                                                {"busy_share", Measure::BusyShare}}};

// The table column a probability may test, and the measure that makes it.
const std::array<std::pair<const char*, Measure>, 15> kColumns{{{"frames_late", Measure::FramesLate},
                                                                {"frames_dropped", Measure::FramesDropped},
                                                                {"frames_caught_up", Measure::FramesCaughtUp},
                                                                {"pop_max", Measure::PopMax},
                                                                {"lag_max", Measure::LagMax},
                                                                {"ring_banks_min", Measure::RingOccupancy},
                                                                {"ring_banks_mean", Measure::RingOccupancy},
                                                                {"ring_underruns", Measure::RingOccupancy},
                                                                {"longest_stall_s", Measure::SurvivableStall},
                                                                {"bitrate_bps", Measure::Coding},
                                                                {"sectors_per_frame", Measure::Coding},
                                                                {"psnr_mean_db", Measure::Coding},
                                                                {"psnr_min_db", Measure::Coding},
                                                                {"ipu_busy_share", Measure::BusyShare},
                                                                {"ee_busy_share", Measure::BusyShare}}};

std::string columnList() {
  std::string list;
  for (std::size_t i = 0; i < kColumns.size(); ++i)
    list += std::string(i == 0 ? "" : i + 1 == kColumns.size() ? " or " : ", ") + kColumns[i].first;
  return list;
}

// [equal_quality]: which re-encode is the reference, and how near is equal (sweep/plan.hpp).
void readEqualQuality(const Section& top, const std::string& origin, SweepPlanSpec& plan) {
  const toml::table* t = subTable(top, "equal_quality");
  if (t == nullptr) return;
  const Section s(origin, *t, "equal_quality",
                  {"reference_gop", "reference_b_frames", "reference_qscale", "tolerance_db"});
  EqualQuality e;
  e.referenceGop = static_cast<int>(s.integer("reference_gop", 1, 1, 1024));
  e.referenceBFrames = static_cast<int>(s.integer("reference_b_frames", 0, 0, 16));
  if (s.get("reference_qscale") == nullptr)
    s.fail(nullptr, "reference_qscale", "missing: the quantiser of the reference re-encode (one of axes.qscales)");
  e.referenceQscale = static_cast<int>(s.integer("reference_qscale", 0, 1, 31));
  if (const toml::node* n = s.get("tolerance_db")) {
    if (!n->is_number() || *n->value<double>() <= 0)
      s.fail(n, "tolerance_db", "expected a PSNR difference in dB above 0, e.g. 0.25");
    e.toleranceDb = *n->value<double>();
  }
  const bool found = std::any_of(plan.streams.begin(), plan.streams.end(), [&](const StreamSpec& x) {
    return x.qscale == e.referenceQscale && x.gop == e.referenceGop && x.bFrames == e.referenceBFrames;
  });
  if (!found) {
    s.fail(s.get("reference_qscale"), "reference_qscale",
           "no re-encode is the reference: axes.qscales must hold " + std::to_string(e.referenceQscale) +
               " and axes.gops { gop = " + std::to_string(e.referenceGop) +
               ", b_frames = " + std::to_string(e.referenceBFrames) + " }");
  }
  if (!hasMeasure(plan, Measure::Coding))
    s.fail(nullptr, "reference_qscale", "needs the PSNR of each re-encode: add \"coding\" to [measures] include");
  plan.equalQuality = e;
}

void readMeasures(const Section& top, const std::string& origin, SweepPlanSpec& plan) {
  if (const toml::table* m = subTable(top, "measures")) {
    const Section s(origin, *m, "measures", {"include"});
    s.array("include", [&](const toml::node& el) {
      const auto name = el.value<std::string>();
      const auto* it =
          std::find_if(kMeasures.begin(), kMeasures.end(), [&](const auto& p) { return name && *name == p.first; });
      if (it == kMeasures.end()) {
        s.fail(&el, "include",
               "expected frames_late, frames_dropped, frames_caught_up, pop_max, lag_max, ring_occupancy, "
               "survivable_stall, coding or busy_share");
      }
      if (!hasMeasure(plan, it->second)) plan.measures.push_back(it->second);
    });
  }
  if (plan.measures.empty()) {
    for (const auto& [name, m] : kMeasures) {
      if (m < Measure::SurvivableStall) plan.measures.push_back(m);  // the defaults before GOP studies
    }
  }
  std::sort(plan.measures.begin(), plan.measures.end());
  plan.search.stallAt = fromMs(3000);
  plan.search.maxStall = fromMs(20000);
  plan.search.resolution = fromMs(50);
  plan.search.settle = fromMs(5000);
  if (const toml::table* t = subTable(top, "stall_search")) {
    const Section s(origin, *t, "stall_search",
                    {"criterion", "stall_at", "max_stall", "resolution", "settle", "pop_threshold"});
    const std::string crit = s.string("criterion", "no-late-frame");
    if (crit != "no-late-frame" && crit != "pop")
      s.fail(s.get("criterion"), "criterion", "expected no-late-frame or pop");
    plan.stallCriterion = crit == "pop" ? Criterion::Pop : Criterion::Late;
    plan.search.stallAt = s.time("stall_at", plan.search.stallAt);
    plan.search.maxStall = s.time("max_stall", plan.search.maxStall);
    plan.search.resolution = s.time("resolution", plan.search.resolution);
    plan.search.settle = s.time("settle", plan.search.settle);
    if (const toml::node* n = s.get("pop_threshold"); n != nullptr && !(n->value<std::string>() == "auto")) {
      plan.search.popThreshold = static_cast<int>(s.integer("pop_threshold", -1, 0, 255));
    }
    if (plan.search.maxStall / plan.search.resolution > 100'000)
      s.fail(s.get("resolution"), "resolution", "max_stall / resolution is above 100000 steps: coarser, please");
  }
  top.array("probability", [&](const toml::node& el) {
    const toml::table* t = el.as_table();
    if (t == nullptr) top.fail(&el, "probability", "expected [[probability]] tables");
    const Section s(origin, *t, "probability", {"name", "measure", "op", "value"});
    Probability p;
    p.measure = s.string("measure", "");
    const auto* col =
        std::find_if(kColumns.begin(), kColumns.end(), [&](const auto& c) { return p.measure == c.first; });
    if (col == kColumns.end()) {
      s.fail(s.get("measure"), "measure", "expected a measured column: " + columnList());
    }
    if (!hasMeasure(plan, col->second)) {
      s.fail(s.get("measure"), "measure",
             "'" + p.measure + "' is not measured: add \"" + toString(col->second) + "\" to [measures] include");
    }
    p.op = s.string("op", "");
    if (p.op != ">" && p.op != ">=" && p.op != "<" && p.op != "<=")
      s.fail(s.get("op"), "op", "expected >, >=, < or <=");
    const toml::node* v = s.get("value");
    if (v == nullptr || !v->is_number()) s.fail(v, "value", "expected the threshold as a number");
    p.threshold = *v->value<double>();
    p.name = s.string("name", "P(" + p.measure + " " + p.op + " " + std::to_string(p.threshold) + ")");
    plan.probabilities.push_back(std::move(p));
  });
}

}  // namespace

SweepPlanSpec parseSweepPlan(std::string_view text, const std::string& origin, const std::string& baseDir) {
  const toml::table doc = parseTomlDocument(text, origin);
  const Section top(origin, doc, "",
                    {"run", "axes", "faults", "measures", "stall_search", "probability", "equal_quality"});
  SweepPlanSpec plan;
  std::uint64_t seed = 1;
  player::PlatformConfig base;
  if (const toml::table* run = subTable(top, "run")) {
    const Section s(origin, *run, "run", {"duration", "seed", "config"});
    plan.duration = s.time("duration", fromMs(20000));
    seed = static_cast<std::uint64_t>(s.integer("seed", 1, 0, INT64_MAX));
    const std::string config = s.string("config", "");
    if (!config.empty()) base = loadPlatformFile(resolve(baseDir, config));
  } else {
    plan.duration = fromMs(20000);
  }
  const toml::table* axesTable = subTable(top, "axes");
  if (axesTable == nullptr) top.fail(nullptr, "axes", "missing: [axes] with at least streams = [\"file.vbim\"]");
  const Section axes(origin, *axesTable, "axes",
                     {"streams", "qscales", "bitrates", "gops", "rings", "policies", "seeds", "platform"});
  readStreams(axes, origin, baseDir, plan);
  readRingsPoliciesSeeds(axes, plan);
  readPlatforms(axes, origin, base, plan);
  readFaults(top, origin, baseDir, seed, plan);
  readMeasures(top, origin, plan);
  readEqualQuality(top, origin, plan);
  return plan;
}

SweepPlanSpec loadSweepPlan(const std::string& path) {
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return parseSweepPlan(readTomlFile(path, "sweep plan"), path, dir);
}

}  // namespace vbim::config
