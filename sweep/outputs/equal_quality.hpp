// A GOP study at equal quality (`[equal_quality]` of a sweep plan, docs/gop-study.md): among the
// cases that differ only in their stream, per GOP structure of the `gops` axis the re-encode whose
// mean luma PSNR against the source is nearest the reference re-encode's (ties: the lower bitrate),
// with its bitrate, sectors per frame, ring occupancy, survivable stall and busy shares as measured.
// Written as equal_quality.csv, equal_quality.md (a table per group of the other axes) and
// plots/equal_quality_<n>.png/.svg (each measure against GOP length, the reference dashed).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sweep/runner.hpp"

namespace vbim::sweep {

// One chosen re-encode of a group.
struct EqualQualityRow {
  std::size_t record = 0;  // index into the records
  const StreamSpec* stream = nullptr;
  double deltaDb = 0;  // its mean PSNR minus the reference's
  bool equal = false;  // |deltaDb| <= tolerance
  bool reference = false;
};

struct EqualQualityGroup {
  std::string label;  // the other axes: "ring 4:8, blend-through, faults none, seed 1"
  double referenceDb = 0;
  std::vector<EqualQualityRow> rows;  // in order of the gops axis
};

// The groups (in case order) of a plan with [equal_quality]; a group whose reference case failed
// is left out, as are failed cases.
std::vector<EqualQualityGroup> equalQualityGroups(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                                  const std::vector<CaseRecord>& records);

// Writes equal_quality.csv, equal_quality.md and the figures into `dir`; returns the names written.
std::vector<std::string> writeEqualQuality(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                           const std::vector<CaseRecord>& records, const std::filesystem::path& dir);

// "intra only", "GOP 12", "GOP 12, 2 B", "GOP 12, 2 B, open".
std::string gopLabel(const StreamSpec& s);

}  // namespace vbim::sweep
