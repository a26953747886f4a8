// `vbim vectors` as library calls: the known-answer vectors (player/known_answers.hpp) of stream
// files, written into an output directory, or a port's captured files scored against them, every
// selected entry of every file with the first differences and where in the value (docs/porting.md,
// "Known-answer vectors"). Not model code (it reads and writes files); the simulated clock's cost
// is none.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "ipu/kernels.hpp"
#include "player/known_answers.hpp"

namespace vbim::runs {

// `vbim vectors`' request checked before any vector is made: exactly one of `out` and `check`,
// `only` with `check` alone, `check` a directory, and an existing, non-empty `out` refused unless
// `force`. Throws vbim::Error naming the option.
void checkVectorsRequest(const std::string& out, const std::string& check, const std::vector<std::string>& only,
                         bool force);

// Without --stream: the two sample streams day_clear.vbim and day_weather.vbim, wherever the program
// finds them (samples.hpp), so that the vectors do not depend on the directory it is run from. Throws
// vbim::Error naming where they were looked for when they are not there.
std::vector<std::string> sampleVectorStreams();

// The vectors of the stream files at `paths`, each named by its stem. A file that cannot be opened
// is a vbim::Error "<label><path>: cannot open the stream file" (`label` is "--stream " when the
// user named the files, "" for the defaults).
std::vector<player::VectorFile> streamVectors(const std::vector<std::string>& paths, const std::string& label,
                                              ipu::IdctKind idct);

// Writes every file into `out` (complete or absent, runs/output_dir.hpp) and returns their lines.
// Throws RunFailure (runs/error.hpp) when a file cannot be written. `beforeCommit`, when given, is
// called with every file written and before the directory takes its name: whatever it throws (the
// command's Ctrl-C) leaves no directory.
std::size_t writeVectors(const std::vector<player::VectorFile>& files, const std::string& out, bool force,
                         const std::function<void()>& beforeCommit = {});

// A port's directory scored against the vectors.
struct VectorsCheck {
  std::string report;       // a line per vector file, then up to three of its differences
  std::size_t present = 0;  // vector files found in the directory (with a selected entry)
  std::size_t checked = 0;  // entries selected in the files present
  std::size_t matched = 0;  // ... equal in the port's files
  bool passed = true;       // every present file passes
  bool anySelected = true;  // when present == 0: false if `only` selects no entry of any file
};

// `only` (vbim vectors --only): a value of stage names (the files' names without .txt, alone or
// comma-separated) selects whole files; any other value is a key pattern (player::scoreVectors).
// Empty: every entry. A file the directory does not have is named absent, not failed: the port has
// not reached that stage yet.
VectorsCheck checkVectors(const std::vector<player::VectorFile>& files, const std::filesystem::path& dir,
                          const std::vector<std::string>& only);

// What `vbim vectors --check DIR` says of `c`: when every present file passes, `passed` and the
// lines to print (how many files match, the entries `only` selected when `onlyGiven`, the report);
// otherwise the message of the failure (no selected file present, or entries that differ: exit 1).
// Throws vbim::Error when no file is present and `only` selects no entry of any (bad input).
struct VectorsVerdict {
  bool passed = false;
  std::string text;
};
VectorsVerdict vectorsVerdict(const VectorsCheck& c, const std::string& dir, bool onlyGiven);

// `vbim vectors` as one call: its options, as the command line gives them.
struct VectorsRequest {
  std::vector<std::string> streams;  // --stream; empty: sampleVectorStreams()
  std::string out;                   // write the vectors here, or
  std::string check;                 // score a port's files here
  std::vector<std::string> only;     // --only: the stages or key patterns checked
  std::string idct = ipu::idctKindName(ipu::kDefaultIdct);
  bool force = false;
};

// The request checked, the vectors computed, then written (the verdict: passed, "wrote N vector files
// (L lines) to OUT") or the port's files scored (vectorsVerdict). `checkpoint`, when given, is called
// once the vectors are computed and again before the output directory takes its name: whatever it
// throws (the command's Ctrl-C) stops the run with nothing written.
VectorsVerdict vectorsRun(const VectorsRequest& r, const std::function<void()>& checkpoint = {});

}  // namespace vbim::runs
