#include "runtime/trace_stream.hpp"

#include <algorithm>
#include <charconv>

#include "runtime/json.hpp"

namespace vbim {

namespace trace_format {

long long nanos(Tick t) {
  // t ticks = t * 1e9 / 147456000 ns = t * 15625 / 2304 ns, rounded half away from zero.
  const bool neg = t < 0;
  const __int128 a = static_cast<__int128>(neg ? -t : t) * 15625;
  const auto ns = static_cast<long long>((a + 1152) / 2304);
  return neg ? -ns : ns;
}

namespace {
// "[-]W.FFF" for ns nanoseconds; returns the end of the text in `out` (at least 26 chars).
char* formatMicros(char* out, long long ns) {
  const bool neg = ns < 0;
  const unsigned long long a = neg ? 0ULL - static_cast<unsigned long long>(ns) : static_cast<unsigned long long>(ns);
  if (neg) *out++ = '-';
  out = std::to_chars(out, out + 21, a / 1000).ptr;
  const auto f = static_cast<unsigned>(a % 1000);
  *out++ = '.';
  *out++ = static_cast<char>('0' + f / 100);
  *out++ = static_cast<char>('0' + f / 10 % 10);
  *out++ = static_cast<char>('0' + f % 10);
  return out;
}
}  // namespace

std::string micros(long long ns) {
  char buf[32];
  return std::string(buf, formatMicros(buf, ns));
}

// VCD time unit is 1 ps; one tick is 6,781.9 ps, so distinct ticks stay distinct.
long long vcdPicoseconds(Tick t) {
  const __int128 a = static_cast<__int128>(t) * 1'000'000'000;  // ps = t * 1e12 / 147456000
  return static_cast<long long>((a + 73'728) / 147'456);
}

// VCD identifier codes: printable ASCII 33..126, base 94.
std::string vcdId(std::size_t n) {
  std::string id;
  do {
    id.push_back(static_cast<char>(33 + n % 94));
    n /= 94;
  } while (n != 0);
  return id;
}

std::string vcdName(std::string s) {
  for (char& c : s) {
    if (c == ' ' || c == '\t') c = '_';
  }
  return s;
}

std::string counterValue(std::int64_t v) {
  return "r" + std::to_string(v);
}

}  // namespace trace_format

using namespace trace_format;

TraceText& operator<<(TraceText& text, Micros m) {
  char buf[32];
  return text << std::string_view(buf, static_cast<std::size_t>(trace_format::formatMicros(buf, m.ns) - buf));
}

TraceStream::TraceStream(std::ostream& json, std::ostream& vcd, TraceDetail detail, Tick window)
    : json_(json), vcd_(vcd), detail_(detail), window_(window) {}

void TraceStream::header(const std::vector<std::string>& tracks, const std::vector<std::string>& counters,
                         const std::vector<std::string>& labels) {
  tracks_ = tracks.size();
  counterNames_ = counters;
  for (const std::string& c : counters) quotedCounters_.push_back(json::quote(c));
  for (const std::string& l : labels) labelAdded(l);
  held_.assign(tracks_, Held{});
  busy_.assign(tracks_, 0);
  shown_.assign(tracks_ + counters.size(), 0);
  for (std::size_t i = 0; i < shown_.size(); ++i) ids_.push_back(vcdId(i));

  json_ << "{\"displayTimeUnit\":\"ns\",\"otherData\":{\"clock\":\"vbim simulated bus clock\",\"tick_hz\":" << kBusHz
        << "},\n\"traceEvents\":[\n";
  sep();
  json_ << R"({"name":"process_name","ph":"M","pid":1,"tid":0,"args":{"name":"vbim model"}})";
  for (std::size_t i = 0; i < tracks_; ++i) {
    sep();
    json_ << R"({"name":"thread_name","ph":"M","pid":1,"tid":)" << i + 1 << R"(,"args":{"name":)"
          << json::quote(tracks[i]) << "}}";
    sep();
    json_ << R"({"name":"thread_sort_index","ph":"M","pid":1,"tid":)" << i + 1 << R"(,"args":{"sort_index":)" << i
          << "}}";
  }

  vcd_ << "$comment vbim simulated bus clock, 147.456 MHz; times in ps $end\n";
  vcd_ << "$timescale 1ps $end\n$scope module vbim $end\n";
  // One 1-bit "busy" wire per track, one signed value per counter.
  for (std::size_t i = 0; i < tracks_; ++i)
    vcd_ << "$var wire 1 " << ids_[i] << ' ' << vcdName(tracks[i]) << "_busy $end\n";
  for (std::size_t i = 0; i < counters.size(); ++i)
    vcd_ << kCounterVar << ids_[tracks_ + i] << ' ' << vcdName(counters[i]) << " $end\n";
  vcd_ << "$upscope $end\n$enddefinitions $end\n";
  vcd_ << "#0\n$dumpvars\n";
  for (std::size_t i = 0; i < tracks_; ++i) vcd_ << "0" << ids_[i] << "\n";
  for (std::size_t i = 0; i < counters.size(); ++i) vcd_ << counterValue(0) << ' ' << ids_[tracks_ + i] << "\n";
  vcd_ << "$end\n";
}

void TraceStream::labelAdded(std::string_view label) {
  quoted_.push_back(json::quote(std::string(label)));
}

void TraceStream::sep() {
  if (!first_) json_ << ",\n";
  first_ = false;
}

void TraceStream::span(std::uint32_t track, Tick begin, Tick end, std::uint32_t label) {
  Held& h = held_[track];
  if (h.begin >= 0 && h.end == begin && h.label == label) {
    h.end = end;  // back to back with the same label: one span
    return;
  }
  if (h.begin >= 0) release(track);
  held_[track] = Held{begin, end, label};
  change(begin, track, 1);
}

void TraceStream::release(std::uint32_t track) {
  Held& h = held_[track];
  // The duration is the difference of the rounded ends, so spans that follow each other on a
  // track never overlap in the file (begin + a rounded duration could pass the next begin by 1 ns).
  const long long b = nanos(h.begin);
  sep();
  json_ << R"({"name":)" << quoted_[h.label] << R"(,"ph":"X","pid":1,"tid":)" << track + 1 << R"(,"ts":)" << Micros{b}
        << R"(,"dur":)" << Micros{nanos(h.end) - b} << "}";
  busy_[track] += h.end - h.begin;
  change(h.end, track, 0);
  h.begin = -1;
}

void TraceStream::instant(std::uint32_t track, Tick t, std::uint32_t label) {
  sep();
  json_ << R"({"name":)" << quoted_[label] << R"(,"ph":"i","pid":1,"tid":)" << track + 1 << R"(,"ts":)"
        << Micros{nanos(t)} << "}";
}

void TraceStream::value(std::uint32_t counter, Tick t, std::int64_t v) {
  sep();
  json_ << R"({"name":)" << quotedCounters_[counter] << R"(,"ph":"C","pid":1,"ts":)" << Micros{nanos(t)}
        << R"(,"args":{"value":)" << v << "}}";
  change(t, static_cast<std::uint32_t>(tracks_ + counter), v);
}

void TraceStream::change(Tick t, std::uint32_t var, std::int64_t v) {
  if (t < written_) {
    ++late_;
    t = written_;
  }
  const Change c{t, seq_++, var, v};
  if (ordered_.empty() || t >= ordered_.back().t) {
    ordered_.push_back(c);  // (t, seq) not before the last one: seq only grows
  } else {
    pending_.push(c);
  }
}

void TraceStream::advance(Tick now) {
  const Tick limit = now - window_;
  if (limit <= written_) return;
  for (std::uint32_t track = 0; track < tracks_; ++track) {
    if (held_[track].begin >= 0 && held_[track].end < limit) release(track);
  }
  flushBefore(limit);
}

void TraceStream::finish() {
  for (std::uint32_t track = 0; track < tracks_; ++track) {
    if (held_[track].begin >= 0) release(track);
  }
  flushBefore(kNever);
  json_ << "\n]}\n";
  json_.flush();
  vcd_.flush();
}

const TraceStream::Change* TraceStream::nextChange() const {
  if (ordered_.empty()) return pending_.empty() ? nullptr : &pending_.top();
  if (pending_.empty() || pending_.top() > ordered_.front()) return &ordered_.front();
  return &pending_.top();
}

void TraceStream::popChange(const Change* c) {
  if (!ordered_.empty() && c == &ordered_.front()) {
    ordered_.pop_front();
  } else {
    pending_.pop();
  }
}

void TraceStream::flushBefore(Tick limit) {
  for (const Change* c = nextChange(); c != nullptr && c->t < limit; c = nextChange()) {
    const Tick t = c->t;
    group_.clear();
    for (; c != nullptr && c->t == t; c = nextChange()) {
      group_.push_back(*c);
      popChange(c);
    }
    writeGroup(t);
  }
  written_ = std::max(written_, limit);
}

void TraceStream::writeGroup(Tick t) {
  const std::vector<Change>* changes = &group_;
  if (detail_ == TraceDetail::Coalesced) {
    // Per variable, the value it ends the instant with, in the order of its last change.
    last_.clear();
    for (const Change& c : group_) {
      auto it = std::find_if(last_.begin(), last_.end(), [&](const Change& l) { return l.var == c.var; });
      if (it != last_.end()) last_.erase(it);
      last_.push_back(c);
    }
    std::erase_if(last_, [&](const Change& c) { return shown_[c.var] == c.v; });
    changes = &last_;
  }
  for (const Change& c : *changes) {
    const long long ps = vcdPicoseconds(t);
    if (ps != lastPs_) {
      vcd_ << '#' << ps << '\n';
      lastPs_ = ps;
    }
    if (c.var < tracks_) {
      vcd_ << (c.v ? '1' : '0') << ids_[c.var] << '\n';
    } else {
      vcd_ << counterValue(c.v) << ' ' << ids_[c.var] << '\n';
    }
    shown_[c.var] = c.v;
  }
}

Tick TraceStream::busyTime(std::uint32_t track, Tick from, Tick to) const {
  Tick sum = busy_[track];
  const Held& h = held_[track];
  if (h.begin >= 0) sum += std::max<Tick>(0, std::min(h.end, to) - std::max(h.begin, from));
  return sum;
}

}  // namespace vbim
