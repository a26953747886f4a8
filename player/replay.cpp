#include "player/replay.hpp"

#include <charconv>
#include <map>
#include <sstream>

#include "gs/arrival_source.hpp"
#include "gs/presenter.hpp"
#include "iop/sector_source.hpp"
#include "ipu/picture_decoder.hpp"
#include "player/frame_hash.hpp"
#include "runtime/error.hpp"
#include "runtime/serial_unit.hpp"
#include "streams/demuxer.hpp"

namespace vbim::player {

std::string arrivalsHeader() {
  return "vsync,stream,frame\n";
}

std::string arrivalLine(const ReplayArrival& a) {
  return std::to_string(a.vsync) + "," + (a.sky ? "sky:" : "lightmap:") + std::to_string(a.variant) + "," +
         std::to_string(a.seq) + "\n";
}

std::string arrivalsEndLine(std::int64_t vsyncs) {
  return std::to_string(vsyncs) + ",end,\n";
}

namespace {

bool parseInt(std::string_view s, std::int64_t& v) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && v >= 0;
}

std::vector<gs::StreamInfo> infos(const streams::Descriptor& d, int index) {
  const streams::StreamEntry& e = d.streams[static_cast<std::size_t>(index)];
  std::vector<gs::StreamInfo> out;
  for (const streams::Variant& v : d.variants) {
    out.push_back(gs::StreamInfo{v.name, e.width, e.height, d.framesPerVariant, d.gameFps.num, d.gameFps.den});
  }
  return out;
}

}  // namespace

ArrivalLog parseArrivals(const std::string& text, const std::string& origin) {
  ArrivalLog log;
  std::istringstream in(text);
  std::string line;
  int n = 0;
  const auto bad = [&](const std::string& what) {
    return ConfigError(origin + ":" + std::to_string(n) + ": " + what +
                       " (expected vsync,stream,frame: e.g. 12,lightmap:0,6; stream lightmap:V or sky:V; "
                       "last, the end row N,end,)");
  };
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (n == 1 && line == "vsync,stream,frame") continue;
    const auto c1 = line.find(',');
    const auto c2 = c1 == std::string::npos ? c1 : line.find(',', c1 + 1);
    if (c2 == std::string::npos || line.find(',', c2 + 1) != std::string::npos) throw bad("'" + line + "'");
    const std::string stream = line.substr(c1 + 1, c2 - c1 - 1);
    if (log.vsyncs) throw bad("'" + line + "' after the end row");
    if (stream == "end") {
      std::int64_t vsyncs = 0;
      if (!parseInt(std::string_view(line).substr(0, c1), vsyncs)) throw bad("end vsync '" + line.substr(0, c1) + "'");
      if (c2 + 1 != line.size()) throw bad("end row '" + line + "' with a frame");
      log.vsyncs = vsyncs;
      continue;
    }
    ReplayArrival a;
    std::int64_t variant = 0;
    const auto colon = stream.find(':');
    const std::string kind = stream.substr(0, colon);
    if (colon == std::string::npos || (kind != "lightmap" && kind != "sky") ||
        !parseInt(std::string_view(stream).substr(colon + 1), variant) || variant > 255) {
      throw bad("stream '" + stream + "'");
    }
    if (!parseInt(std::string_view(line).substr(0, c1), a.vsync)) throw bad("vsync '" + line.substr(0, c1) + "'");
    if (!parseInt(std::string_view(line).substr(c2 + 1), a.seq)) throw bad("frame '" + line.substr(c2 + 1) + "'");
    a.sky = kind == "sky";
    a.variant = static_cast<int>(variant);
    log.arrivals.push_back(a);
  }
  return log;
}

struct Replay::Impl {
  ReplayOptions options;
  streams::Descriptor descriptor;
  std::map<std::pair<int, std::uint32_t>, std::vector<std::uint8_t>> pictures;  // (stream id, global frame)
  Scheduler sched;
  SerialUnit gs{sched};
  std::unique_ptr<gs::ArrivalSource> lmSource, skySource;
  std::unique_ptr<gs::Presenter> lightmap, sky;
};

Replay::Replay(std::span<const std::uint8_t> file, const std::string& name, const std::vector<ReplayArrival>& arrivals,
               ReplayOptions options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.options = std::move(options);
  validate(m.options.config);
  streams::Demuxer demux;
  for (std::size_t i = 0; i + iop::kSectorBytes <= file.size(); i += iop::kSectorBytes) {
    demux.feed(file.subspan(i, iop::kSectorBytes), static_cast<std::uint32_t>(i / iop::kSectorBytes));
  }
  demux.finish();
  if (!demux.descriptor()) throw ConfigError(name + ": no VBIM playback descriptor (not a VBIM stream)");
  m.descriptor = *demux.descriptor();
  for (streams::Picture& p : demux.pictures()) {
    if (p.frame && !p.damaged) m.pictures[{p.streamId, *p.frame}] = std::move(p.data);
  }
  const int lmIndex = m.descriptor.streamIndex(0xE0);
  const int skyIndex = m.descriptor.streamIndex(0xE1);
  if (lmIndex < 0) throw ConfigError(name + ": the descriptor has no lightmap stream (0xE0)");
  const auto variants = static_cast<int>(m.descriptor.variants.size());
  std::vector<gs::Arrival> lm, sky;
  for (const ReplayArrival& a : arrivals) {
    if (a.variant >= variants) {
      throw ConfigError(name + ": an arrival at vsync " + std::to_string(a.vsync) + " names variant " +
                        std::to_string(a.variant) + ", but the stream has " + std::to_string(variants));
    }
    if (a.sky && skyIndex < 0) {
      throw ConfigError(name + ": an arrival at vsync " + std::to_string(a.vsync) +
                        " names the sky, but the "
                        "stream has none");
    }
    (a.sky ? sky : lm).push_back(gs::Arrival{a.vsync, a.variant, a.seq});
  }
  const VsyncClock clock = [&] {
    VsyncRate rate{};
    if (!vsyncRateByName(m.options.config.gs.video, rate)) throw ConfigError("unknown gs.video mode");
    return VsyncClock(rate);
  }();
  const auto imageFn = [this](int id) {
    return [this, id](int variant, std::int64_t streamFrame) {
      Impl& im = *impl_;
      const auto global =
          static_cast<std::uint32_t>(variant * static_cast<std::int64_t>(im.descriptor.framesPerVariant) + streamFrame);
      const streams::StreamEntry& e =
          im.descriptor.streams[static_cast<std::size_t>(im.descriptor.streamIndex(static_cast<std::uint8_t>(id)))];
      Rgba8Image out(e.width, e.height);
      const auto it = im.pictures.find({id, global});
      if (it == im.pictures.end()) {
        ++missing_;
        return out;
      }
      ipu::DecoderOptions o;
      o.kernels = im.options.kernels.ipu;
      o.idct = ipu::idctKindOf(im.options.config.ipu);
      ipu::Decoder decoder(o);
      ipu::decodeToRgba(decoder, it->second, out);
      return out;
    };
  };
  const Tick t0 = fromMs(m.options.config.ee.start_lead_ms);
  const auto presenterOptions = [&](const char* track) {
    gs::PresenterOptions o;
    o.t0 = t0;
    o.gs = &m.gs;
    o.kernels = m.options.kernels.blend;
    o.name = track;
    o.keepHistory = false;
    return o;
  };
  // One VRAM plan for both presenters, as in Pipeline: the lightmap's holds the sky's staging area.
  gs::PresenterOptions lightmapOptions = presenterOptions("gs");
  if (skyIndex >= 0) {
    const streams::StreamEntry& e = m.descriptor.streams[static_cast<std::size_t>(skyIndex)];
    lightmapOptions.sky = gs::SkyTexture{e.width, e.height};
  }
  m.lmSource = std::make_unique<gs::ArrivalSource>(infos(m.descriptor, lmIndex), imageFn(0xE0), clock, lm);
  m.lightmap = std::make_unique<gs::Presenter>(m.sched, *m.lmSource, m.options.config.gs, std::move(lightmapOptions));
  if (skyIndex >= 0) {
    gs::PresenterOptions skyOptions = presenterOptions("gs.sky");
    skyOptions.console = &m.lightmap->vram();
    m.skySource = std::make_unique<gs::ArrivalSource>(infos(m.descriptor, skyIndex), imageFn(0xE1), clock, sky);
    m.sky = std::make_unique<gs::Presenter>(m.sched, *m.skySource, m.options.config.gs, std::move(skyOptions));
  }
  // Vsync n is presented when its time is before the duration (record): this one presents exactly n < N.
  if (m.options.vsyncs) m.options.duration = m.lightmap->clock().time(*m.options.vsyncs);
}

Replay::~Replay() = default;

Task<void> Replay::record(Replay& r) {
  Impl& m = *r.impl_;
  const VsyncClock clock = m.lightmap->clock();
  for (std::int64_t n = 0; clock.time(n) < m.options.duration; ++n) {
    for (gs::Presenter* p : {m.lightmap.get(), m.sky.get()}) {
      if (p == nullptr) continue;
      while (p->presented() <= n) co_await p->presentedEvent().wait();
    }
    VsyncRow row;
    row.vsync = n;
    row.lightmap = m.lightmap->last();
    row.at = row.lightmap.at;
    const Rgba8Image* sky = m.sky ? &m.sky->lightmap() : nullptr;
    if (m.sky) row.sky = m.sky->last();
    row.hash = frameHash(m.lightmap->lightmap(), sky);
    if (r.sink_) r.sink_(row, m.lightmap->lightmap(), sky);
  }
}

void Replay::run() {
  Impl& m = *impl_;
  m.sched.spawn("gs", m.lightmap->run(m.options.duration));
  if (m.sky) m.sched.spawn("gs.sky", m.sky->run(m.options.duration));
  m.sched.spawn("replay.record", record(*this));
  m.sched.runUntil(m.options.duration);
}

}  // namespace vbim::player
