#include "streams/info/stream_info.hpp"

#include "streams/format.hpp"

namespace vbim::streams {

namespace {

nlohmann::json summaryJson(const Summary& s) {
  return {{"min", s.min}, {"mean", s.mean}, {"max", s.max}};
}

nlohmann::json descriptorJson(const Descriptor& d) {
  nlohmann::json j;
  j["game_fps"] = {{"num", d.gameFps.num}, {"den", d.gameFps.den}};
  j["frames_per_variant"] = d.framesPerVariant;
  j["loop_frame"] = d.loopFrame;
  j["first_pts"] = d.firstPts;
  j["pts_per_frame"] = d.ptsPerFrame;
  j["descriptor_sectors"] = d.descriptorSectors;
  j["total_sectors"] = d.totalSectors;
  for (const StreamEntry& s : d.streams) {
    j["streams"].push_back({{"id", hexId(s.id)},
                            {"role", s.role == StreamRole::Lightmap ? "lightmap" : "sky"},
                            {"width", s.width},
                            {"height", s.height}});
  }
  for (const Variant& v : d.variants)
    j["variants"].push_back({{"name", v.name}, {"first_frame", v.firstFrame}, {"first_sector", v.firstSector}});
  j["version"] = d.intraOnly() ? Descriptor::kVersionIntra : Descriptor::kVersion;
  for (std::size_t s = 0; s < d.index.size(); ++s) {
    nlohmann::json sectors = nlohmann::json::array();
    std::string types;  // frame order; lower case where a GOP starts
    for (const IndexEntry& e : d.index[s]) {
      sectors.push_back(e.sector);
      types += e.gopStart ? "i" : pictureTypeName(e.type);
    }
    j["index_sectors"][hexId(d.streams[s].id)] = sectors;
    j["index_types"][hexId(d.streams[s].id)] = types;
  }
  return j;
}

nlohmann::json typesJson(const StreamReport& r) {
  nlohmann::json j;
  for (std::size_t t = 0; t < r.types.size(); ++t) {
    const TypeReport& tr = r.types[t];
    j[pictureTypeName(static_cast<PictureType>(t + 1))] = {
        {"pictures", tr.pictures}, {"bytes", summaryJson(tr.bytes)}, {"mean_bits", tr.bytes.mean * 8}};
  }
  j["unknown"] = r.unknownType;
  return j;
}

nlohmann::json gopJson(const StreamReport& r) {
  nlohmann::json shapes = nlohmann::json::array();
  for (const GopShape& g : r.shapes) shapes.push_back({{"pattern", g.pattern}, {"count", g.count}});
  return {{"count", r.gops},
          {"closed", r.closedGops},
          {"open", r.gops - r.closedGops},
          {"pictures", summaryJson(r.gopPictures)},
          {"shapes", shapes}};
}

}  // namespace

nlohmann::json infoJson(const StreamInfo& info) {
  const std::optional<iop::DiscFile>& onImage = info.onImage;
  const StreamScan& scan = info.scan;
  const std::optional<nlohmann::ordered_json>& record = info.record;
  nlohmann::json j;
  j["file"] = info.path;
  if (onImage) j["disc_file"] = {{"path", onImage->path}, {"lba", onImage->lba}, {"bytes", onImage->bytes}};
  j["bytes"] = scan.fileBytes;
  j["sectors"] = scan.sectors;
  j["every_pack_2048"] = scan.every2048;
  j["mux_rate_bps"] = scan.muxRate * 400.0;
  j["descriptor"] = scan.descriptor ? descriptorJson(*scan.descriptor) : nlohmann::json(nullptr);
  if (record) j["authoring"] = nlohmann::json::parse(record->dump());
  for (const StreamReport& r : info.reports) {
    nlohmann::json pictures = nlohmann::json::array();
    for (const PictureRecord& p : scan.pictures) {
      if (p.streamId == r.id) {
        pictures.push_back({{"first_sector", p.firstSector},
                            {"last_sector", p.lastSector},
                            {"bytes", p.bytes},
                            {"frame", p.frame ? nlohmann::json(*p.frame) : nlohmann::json(nullptr)},
                            {"type", p.header ? nlohmann::json(pictureTypeName(p.header->type)) : nlohmann::json()},
                            {"gop_start", p.header && p.header->gopHeader},
                            {"damaged", p.damaged}});
      }
    }
    j["streams"].push_back(
        {{"id", hexId(r.id)},
         {"pictures", r.pictures},
         {"bytes_per_picture", summaryJson(r.bytes)},
         {"picture_types", typesJson(r)},
         {"gops", gopJson(r)},
         {"sectors_per_picture", summaryJson(r.spanSectors)},
         {"sectors_per_frame", summaryJson(r.stepSectors)},
         {"worst_run", {{"frames", r.runFrames}, {"sectors", r.runSectors}, {"start_frame", r.runStart}}},
         {"bits_per_second_per_frame", r.bitsPerSecond},
         {"picture_list", pictures}});
  }
  for (const StreamError& e : scan.errors) {
    j["errors"].push_back(
        {{"kind", toString(e.kind)}, {"sector", e.sector}, {"byte_offset", e.byteOffset}, {"message", e.message}});
  }
  if (!j.contains("errors")) j["errors"] = nlohmann::json::array();
  return j;
}

std::string infoJsonText(const StreamInfo& info, bool& replaced) {
  const nlohmann::json j = infoJson(info);
  replaced = false;
  try {
    return j.dump(2);
  } catch (const nlohmann::json::type_error&) {
    replaced = true;
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
  }
}

}  // namespace vbim::streams
