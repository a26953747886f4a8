// An output directory that is complete or absent: files are written into a temporary sibling
// directory, which is renamed onto the final name by commit(). If the program fails before
// commit(), the temporary directory is removed and the final name is left untouched. Every command
// that writes a directory writes it through one (play, replay, decode, render, lightmap, profile,
// vectors, demo). Errors are vbim::Error naming the path (bad input: an output that exists, a
// parent that cannot be made).
#pragma once

#include <filesystem>
#include <string>

namespace vbim::runs {

// `--out dir`, `--out dir/` and `--out ./dir` name the same directory: the path without a trailing
// separator, `.` and `..` resolved lexically.
std::filesystem::path outputPath(const std::filesystem::path& given);

// Refuses (vbim::Error) before any work starts: an output directory that exists and is
// not empty unless `force`, or a path that exists and is not a directory.
void refuseExistingOutputDir(const std::filesystem::path& final, bool force);
// The same for a command that writes one file (vbim author): refused if it exists unless `force`,
// and always if it is a directory.
void refuseExistingOutputFile(const std::filesystem::path& file, bool force);

class OutputDir {
 public:
  // Fails (vbim::Error) if `final` exists, is not empty and `force` is false.
  OutputDir(const std::filesystem::path& final, bool force);
  ~OutputDir();
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;

  // Path of a file inside the temporary directory.
  std::filesystem::path path(const std::string& name) const { return tmp_ / name; }
  // The temporary directory itself, for a library that writes several files into it.
  const std::filesystem::path& directory() const { return tmp_; }
  const std::filesystem::path& finalPath() const { return final_; }
  void commit();

 private:
  std::filesystem::path final_;
  std::filesystem::path tmp_;
  bool force_;
  bool committed_ = false;
};

}  // namespace vbim::runs
