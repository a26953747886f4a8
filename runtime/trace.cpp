#include "runtime/trace.hpp"

#include <algorithm>
#include <ostream>
#include <stdexcept>

#include "runtime/json.hpp"

namespace vbim {

using namespace trace_format;

Tracer::~Tracer() = default;

void Tracer::streamTo(std::ostream& json, std::ostream& vcd, TraceDetail detail, Tick window) {
  if (!enabled_) return;
  stream_ = std::make_unique<TraceStream>(json, vcd, detail, window);
  detail_ = detail;
  headerWritten_ = false;
}

TraceStream* Tracer::live() {
  if (!stream_) return nullptr;
  if (!headerWritten_) {
    headerWritten_ = true;
    stream_->header(tracks_, counters_, labels_);
  }
  return stream_.get();
}

void Tracer::advance(Tick now) {
  if (TraceStream* st = live()) st->advance(now);
}

void Tracer::finish() {
  if (TraceStream* st = live()) st->finish();
}

Tracer::TrackId Tracer::track(std::string name) {
  if (headerWritten_) throw std::logic_error("Tracer::track('" + name + "') after the trace stream started");
  tracks_.push_back(std::move(name));
  open_.emplace_back();
  lastSpan_.push_back(static_cast<std::size_t>(-1));
  return static_cast<TrackId>(tracks_.size() - 1);
}

Tracer::CounterId Tracer::counter(std::string name) {
  if (headerWritten_) throw std::logic_error("Tracer::counter('" + name + "') after the trace stream started");
  counters_.push_back(std::move(name));
  last_.push_back(0);
  hasLast_.push_back(false);
  return static_cast<CounterId>(counters_.size() - 1);
}

std::uint32_t Tracer::intern(std::string_view s) {
  // Every span looks its label up (about 5,000 a simulated second at 512x512). Labels are nearly
  // always string literals, so a small cache by address answers first (a 600 s play at 512x512
  // misses it fewer than 70 times in 2.9 M lookups); its text is compared too, since an address alone
  // could be a buffer reused for another label. A miss scans the labels.
  RecentLabel& recent = recentLabels_[(reinterpret_cast<std::uintptr_t>(s.data()) >> 3) % recentLabels_.size()];
  if (recent.data == s.data() && recent.data != nullptr && labels_[recent.id] == s) return recent.id;
  const auto it = std::find(labels_.begin(), labels_.end(), s);
  const auto id = static_cast<std::uint32_t>(it - labels_.begin());
  if (it == labels_.end()) {
    labels_.emplace_back(s);
    if (stream_ && headerWritten_) stream_->labelAdded(s);
  }
  recent = RecentLabel{s.data(), id};
  return id;
}

void Tracer::span(TrackId track, Tick b, Tick e, std::string_view what) {
  if (!enabled_ || e < b) return;
  const std::uint32_t label = intern(what);
  if (TraceStream* st = live()) {
    st->span(track, b, e, label);
    return;
  }
  const std::size_t last = lastSpan_[track];
  if (last != static_cast<std::size_t>(-1)) {
    Span& prev = spans_[last];
    if (prev.end == b && prev.label == label) {
      prev.end = e;
      return;
    }
  }
  lastSpan_[track] = spans_.size();
  spans_.push_back(Span{track, b, e, label, false});
}

void Tracer::begin(TrackId track, Tick t, std::string_view what) {
  if (!enabled_) return;
  open_[track] = Open{t, intern(what)};
}

void Tracer::end(TrackId track, Tick t) {
  if (!enabled_ || open_[track].begin < 0) return;
  const Open o = open_[track];
  open_[track].begin = -1;
  span(track, o.begin, t, labels_[o.label]);
}

void Tracer::instant(TrackId track, Tick t, std::string_view what) {
  if (!enabled_) return;
  const std::uint32_t label = intern(what);
  if (TraceStream* st = live()) {
    st->instant(track, t, label);
    return;
  }
  spans_.push_back(Span{track, t, t, label, true});
}

void Tracer::value(CounterId c, Tick t, std::int64_t v) {
  if (!enabled_) return;
  if (hasLast_[c] && last_[c] == v) return;
  hasLast_[c] = true;
  last_[c] = v;
  if (TraceStream* st = live()) {
    st->value(c, t, v);
    return;
  }
  samples_.push_back(Sample{c, t, v});
}

Tick Tracer::busyTime(TrackId track, Tick from, Tick to) const {
  if (stream_) return headerWritten_ ? stream_->busyTime(track, from, to) : 0;
  Tick sum = 0;
  for (const Span& s : spans_) {
    if (s.track != track || s.instant) continue;
    const Tick b = std::max(s.begin, from);
    const Tick e = std::min(s.end, to);
    if (e > b) sum += e - b;
  }
  return sum;
}

void Tracer::writeChromeJson(std::ostream& out) const {
  // Written by hand, line per event, so the bytes depend on nothing but the recorded data.
  out << "{\"displayTimeUnit\":\"ns\",\"otherData\":{\"clock\":\"vbim simulated bus clock\",\"tick_hz\":" << kBusHz
      << "},\n\"traceEvents\":[\n";
  bool first = true;
  auto sep = [&] {
    if (!first) out << ",\n";
    first = false;
  };
  sep();
  out << R"({"name":"process_name","ph":"M","pid":1,"tid":0,"args":{"name":"vbim model"}})";
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    sep();
    out << R"({"name":"thread_name","ph":"M","pid":1,"tid":)" << i + 1 << R"(,"args":{"name":)"
        << json::quote(tracks_[i]) << "}}";
    sep();
    out << R"({"name":"thread_sort_index","ph":"M","pid":1,"tid":)" << i + 1 << R"(,"args":{"sort_index":)" << i
        << "}}";
  }
  std::vector<std::string> quoted;
  quoted.reserve(labels_.size());
  for (const auto& l : labels_) quoted.push_back(json::quote(l));
  for (const Span& s : spans_) {
    sep();
    if (s.instant) {
      out << R"({"name":)" << quoted[s.label] << R"(,"ph":"i","pid":1,"tid":)" << s.track + 1 << R"(,"ts":)"
          << micros(nanos(s.begin)) << "}";
    } else {
      out << R"({"name":)" << quoted[s.label] << R"(,"ph":"X","pid":1,"tid":)" << s.track + 1 << R"(,"ts":)"
          << micros(nanos(s.begin)) << R"(,"dur":)" << micros(nanos(s.end) - nanos(s.begin)) << "}";
    }
  }
  for (const Sample& s : samples_) {
    sep();
    out << R"({"name":)" << json::quote(counters_[s.counter]) << R"(,"ph":"C","pid":1,"ts":)" << micros(nanos(s.t))
        << R"(,"args":{"value":)" << s.v << "}}";
  }
  out << "\n]}\n";
}

void Tracer::writeVcd(std::ostream& out) const {
  out << "$comment vbim simulated bus clock, 147.456 MHz; times in ps $end\n";
  out << "$timescale 1ps $end\n$scope module vbim $end\n";
  // One 1-bit "busy" wire per track, one signed value per counter.
  for (std::size_t i = 0; i < tracks_.size(); ++i)
    out << "$var wire 1 " << vcdId(i) << ' ' << vcdName(tracks_[i]) << "_busy $end\n";
  for (std::size_t i = 0; i < counters_.size(); ++i)
    out << kCounterVar << vcdId(tracks_.size() + i) << ' ' << vcdName(counters_[i]) << " $end\n";
  out << "$upscope $end\n$enddefinitions $end\n";

  struct Change {
    Tick t;
    std::size_t order;
    std::size_t var;
    std::int64_t v;
  };
  std::vector<Change> changes;
  changes.reserve(spans_.size() * 2 + samples_.size());
  std::size_t order = 0;
  for (const Span& s : spans_) {
    if (s.instant) continue;
    changes.push_back({s.begin, order++, s.track, 1});
    changes.push_back({s.end, order++, s.track, 0});
  }
  for (const Sample& s : samples_) changes.push_back({s.t, order++, tracks_.size() + s.counter, s.v});
  // Time order; at equal times a span's end sorts before a later span's begin on the same track
  // because ends are recorded before the next begin.
  std::stable_sort(changes.begin(), changes.end(),
                   [](const Change& a, const Change& b) { return a.t != b.t ? a.t < b.t : a.order < b.order; });
  out << "#0\n$dumpvars\n";
  for (std::size_t i = 0; i < tracks_.size(); ++i) out << "0" << vcdId(i) << "\n";
  for (std::size_t i = 0; i < counters_.size(); ++i) out << counterValue(0) << ' ' << vcdId(tracks_.size() + i) << "\n";
  out << "$end\n";
  long long lastPs = 0;
  for (const Change& c : changes) {
    const long long ps = vcdPicoseconds(c.t);
    if (ps != lastPs) {
      out << '#' << ps << '\n';
      lastPs = ps;
    }
    if (c.var < tracks_.size()) {
      out << (c.v ? '1' : '0') << vcdId(c.var) << '\n';
    } else {
      out << counterValue(c.v) << ' ' << vcdId(c.var) << '\n';
    }
  }
}

}  // namespace vbim
