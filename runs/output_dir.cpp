#include "runs/output_dir.hpp"

#include "runtime/error.hpp"
#include "streams/temporary_files.hpp"

namespace vbim::runs {

namespace fs = std::filesystem;

fs::path outputPath(const fs::path& given) {
  fs::path p = given.lexically_normal();
  // "dir/" normalises to "dir/", whose filename is empty: the directory is its parent path.
  if (p.filename().empty() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p;
}

void refuseExistingOutputDir(const fs::path& given, bool force) {
  const fs::path final = outputPath(given);
  std::error_code ec;
  if (!fs::exists(final, ec)) return;
  if (!fs::is_directory(final, ec)) throw Error("--out " + final.string() + ": exists and is not a directory");
  if (!force && !fs::is_empty(final, ec))
    throw Error("--out " + final.string() + ": exists and is not empty (use --force to replace it)");
}

void refuseExistingOutputFile(const fs::path& file, bool force) {
  std::error_code ec;
  if (fs::is_directory(file, ec))
    throw Error("--out " + file.string() + ": is a directory; expected the name of the file to write");
  if (!force && fs::exists(file, ec)) throw Error("--out " + file.string() + ": exists (use --force to replace it)");
}

OutputDir::OutputDir(const fs::path& final, bool force) : final_(outputPath(final)), force_(force) {
  refuseExistingOutputDir(final_, force_);
  std::error_code ec;
  const fs::path parent = final_.has_parent_path() ? final_.parent_path() : fs::path(".");
  fs::create_directories(parent, ec);
  if (ec) throw Error(parent.string() + ": cannot create the directory: " + ec.message());
  // What a killed run left here goes first (streams/temporary_files.hpp), then ours is made.
  streams::removeStaleTemporaries(parent);
  tmp_ = streams::temporarySibling(final_);
  fs::remove_all(tmp_, ec);
  fs::create_directory(tmp_, ec);
  if (ec) throw Error(tmp_.string() + ": cannot create the temporary output directory: " + ec.message());
}

OutputDir::~OutputDir() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(tmp_, ec);
  }
}

void OutputDir::commit() {
  std::error_code ec;
  if (fs::exists(final_, ec)) {
    // Move the old directory aside first so the final name never holds a mix of old and new.
    const fs::path old = tmp_.string() + ".old";
    fs::remove_all(old, ec);
    fs::rename(final_, old, ec);
    if (ec) throw Error(final_.string() + ": cannot replace the existing directory: " + ec.message());
    fs::remove_all(old, ec);
  }
  fs::rename(tmp_, final_, ec);
  if (ec) throw Error(final_.string() + ": cannot move the finished output into place: " + ec.message());
  committed_ = true;
}

}  // namespace vbim::runs
