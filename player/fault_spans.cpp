#include "player/fault_spans.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <tuple>

#include "runtime/error.hpp"

namespace vbim::player {

std::vector<FaultSpan> plannedFaultSpans(const iop::FaultPlan& plan, Tick duration) {
  std::vector<FaultSpan> spans;
  const auto add = [&](const char* kind, Tick begin, Tick end) {
    begin = std::max<Tick>(begin, 0);
    end = std::min(end, duration);
    if (end > begin) spans.push_back(FaultSpan{kind, toSeconds(begin), toSeconds(end)});
  };
  for (const iop::Fault& f : plan.faults) {
    switch (f.kind) {
      case iop::Fault::Kind::Stall:
        add("stall", f.at, f.at + f.duration);
        break;
      case iop::Fault::Kind::Contention:
        add("contention", f.at, f.at + f.duration);
        break;
      case iop::Fault::Kind::RandomStall:
        add("random stalls", f.at, f.at + f.duration);
        break;
      case iop::Fault::Kind::RandomError:
        add("random errors", f.at, f.at + f.duration);
        break;
      case iop::Fault::Kind::SeekAway:
        add("seek away", f.at, f.at + kBusHz / 60);
        break;
      case iop::Fault::Kind::ReadError:
        break;  // no time in the plan: ReadErrorSpans sees when the drive met it
    }
  }
  return spans;
}

void ReadErrorSpans::onVsync(Tick at, std::int64_t retriesSoFar) {
  if (retriesSoFar > retries_) {
    if (openBegin_ < 0) openBegin_ = previous_;
    openEnd_ = at;
  } else if (openBegin_ >= 0) {
    done_.push_back(FaultSpan{"read error", toSeconds(openBegin_), toSeconds(openEnd_)});
    openBegin_ = -1;
  }
  retries_ = retriesSoFar;
  previous_ = at;
}

std::vector<FaultSpan> ReadErrorSpans::spans() const {
  std::vector<FaultSpan> all = done_;
  if (openBegin_ >= 0) all.push_back(FaultSpan{"read error", toSeconds(openBegin_), toSeconds(openEnd_)});
  return all;
}

std::vector<FaultSpan> mergeFaultSpans(std::vector<FaultSpan> planned, const std::vector<FaultSpan>& observed) {
  planned.insert(planned.end(), observed.begin(), observed.end());
  std::stable_sort(planned.begin(), planned.end(), [](const FaultSpan& a, const FaultSpan& b) {
    return std::tie(a.beginS, a.kind) < std::tie(b.beginS, b.kind);
  });
  return planned;
}

void writeFaultSpansCsv(std::ostream& out, const std::vector<FaultSpan>& spans) {
  out << "kind,begin_s,end_s\n";
  for (const FaultSpan& s : spans) {
    char line[128];
    std::snprintf(line, sizeof line, "%s,%.6f,%.6f\n", s.kind.c_str(), s.beginS, s.endS);
    out << line;
  }
}

std::vector<FaultSpan> readFaultSpansCsv(const std::filesystem::path& file) {
  std::vector<FaultSpan> spans;
  std::ifstream in(file);
  if (!in) return spans;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    if (++lineNo == 1 || line.empty()) continue;
    const std::size_t a = line.find(','), b = a == std::string::npos ? a : line.find(',', a + 1);
    try {
      if (b == std::string::npos) throw std::invalid_argument("fields");
      FaultSpan s{line.substr(0, a), std::stod(line.substr(a + 1, b - a - 1)), std::stod(line.substr(b + 1))};
      if (s.kind.empty() || !(s.endS >= s.beginS)) throw std::invalid_argument("span");
      spans.push_back(std::move(s));
    } catch (const std::exception&) {
      throw Error(file.string() + ":" + std::to_string(lineNo) +
                  ": expected kind,begin_s,end_s (a name, then two times in seconds, begin <= end)");
    }
  }
  return spans;
}

}  // namespace vbim::player
