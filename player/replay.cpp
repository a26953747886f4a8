#include "player/replay.hpp"

#include <map>
#include <tuple>

#include "ee/timeline.hpp"
#include "gs/arrival_source.hpp"
#include "gs/presenter.hpp"
#include "iop/sector_source.hpp"
#include "ipu/picture_decoder.hpp"
#include "player/frame_hash.hpp"
#include "player/port_frames.hpp"
#include "player/stream_frame_decoder.hpp"
#include "runtime/error.hpp"
#include "runtime/serial_unit.hpp"
#include "streams/demuxer.hpp"

namespace vbim::player {

namespace {

std::vector<gs::StreamInfo> infos(const streams::Descriptor& d, int index) {
  const streams::StreamEntry& e = d.streams[static_cast<std::size_t>(index)];
  std::vector<gs::StreamInfo> out;
  for (const streams::Variant& v : d.variants) {
    out.push_back(gs::StreamInfo{v.name, e.width, e.height, d.framesPerVariant, d.gameFps.num, d.gameFps.den});
  }
  return out;
}

// The picture number of timeline frame `seq` of a variant: seq -> the stream frame as play's timeline
// maps it (after a wrap, from the descriptor's loop frame), in that variant's run of pictures.
std::int64_t pictureOf(const streams::Descriptor& d, int variant, std::int64_t seq) {
  return variant * static_cast<std::int64_t>(d.framesPerVariant) + ee::Timeline(d).frameInVariant(seq);
}

}  // namespace

struct Replay::Impl {
  ReplayOptions options;
  streams::Descriptor descriptor;
  std::map<std::pair<int, std::uint32_t>, std::vector<std::uint8_t>> pictures;  // (stream id, global frame)
  Scheduler sched;
  SerialUnit gs{sched};
  std::unique_ptr<gs::ArrivalSource> lmSource, skySource;
  std::unique_ptr<gs::Presenter> lightmap, sky;
  std::map<std::tuple<bool, int, std::int64_t>, ReplayArrival> arrivals;  // (sky, variant, frame)
  std::map<int, std::unique_ptr<StreamFrameDecoder>> frameDecoders;       // by stream id
  Tick t0 = 0;
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
    const std::string where =
        "an arrival at vsync " + std::to_string(a.vsync) + (a.line > 0 ? " (line " + std::to_string(a.line) + ")" : "");
    if (a.variant >= variants) {
      throw ConfigError(name + ": " + where + " names variant " + std::to_string(a.variant) + ", but the stream has " +
                        std::to_string(variants));
    }
    if (a.sky && skyIndex < 0) throw ConfigError(name + ": " + where + " names the sky, but the stream has none");
    (a.sky ? sky : lm).push_back(gs::Arrival{a.vsync, a.variant, a.seq});
    m.arrivals[{a.sky, a.variant, a.seq}] = a;
    if (m.options.frames) {
      // Every picture the log names must be there, checked before anything is presented.
      const streams::StreamEntry& e = m.descriptor.streams[static_cast<std::size_t>(a.sky ? skyIndex : lmIndex)];
      const std::int64_t picture = pictureOf(m.descriptor, a.variant, a.seq);
      m.options.frames->check(a.sky, picture, e.width, e.height,
                              std::string(a.sky ? "the sky" : "the lightmap") + " picture " + std::to_string(picture) +
                                  " (variant " + std::to_string(a.variant) + ", timeline frame " +
                                  std::to_string(a.seq) + "), named by " + where);
    }
  }
  const VsyncClock clock = [&] {
    VsyncRate rate{};
    if (!vsyncRateByName(m.options.config.gs.video, rate)) throw ConfigError("unknown gs.video mode");
    return VsyncClock(rate);
  }();
  for (const int id : {0xE0, 0xE1}) {
    const int index = m.descriptor.streamIndex(static_cast<std::uint8_t>(id));
    if (index < 0) continue;
    ipu::DecoderOptions o;
    o.kernels = m.options.kernels.ipu;
    o.idct = ipu::idctKindOf(m.options.config.ipu);
    m.frameDecoders[id] = std::make_unique<StreamFrameDecoder>(
        m.descriptor, index, o, [this, id](std::uint32_t global) -> std::span<const std::uint8_t> {
          const auto it = impl_->pictures.find({id, global});
          if (it == impl_->pictures.end()) return {};
          return it->second;
        });
  }
  const auto imageFn = [this](int id) {
    // seq -> the stream frame as play's timeline maps it: after a wrap, from the descriptor's loop frame.
    return [this, id](int variant, std::int64_t seq) {
      Impl& im = *impl_;
      const std::int64_t picture = pictureOf(im.descriptor, variant, seq);
      const auto global = static_cast<std::uint32_t>(picture);
      const streams::StreamEntry& e =
          im.descriptor.streams[static_cast<std::size_t>(im.descriptor.streamIndex(static_cast<std::uint8_t>(id)))];
      if (im.options.frames) return im.options.frames->read(id == 0xE1, picture, e.width, e.height);
      Rgba8Image out(e.width, e.height);
      if (!im.frameDecoders.at(id)->decode(global, out)) ++missing_;
      return out;
    };
  };
  const Tick t0 = fromMs(m.options.config.ee.start_lead_ms);
  m.t0 = t0;
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

std::int64_t Replay::dueVsync(std::int64_t seq) const {
  const Impl& m = *impl_;
  return gs::firstVsyncAtOrAfter(m.lightmap->clock(), gs::dueTime(m.lmSource->streams().front(), m.t0, seq));
}

const ReplayArrival* Replay::arrivalOf(bool sky, int variant, std::int64_t seq) const {
  const auto it = impl_->arrivals.find({sky, variant, seq});
  return it == impl_->arrivals.end() ? nullptr : &it->second;
}

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
