#include "streams/disc/iso_writer.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>

#include "iop/error.hpp"
#include "streams/disc/iso_disc.hpp"
#include "streams/temporary_files.hpp"

extern char** environ;  // NOLINT(readability-redundant-declaration): POSIX leaves it undeclared

namespace vbim::streams {

namespace {

// A graft point "DISC=HOST" of `xorriso -as mkisofs -graft-points`: '=' and '\' in either side are
// escaped with a backslash (xorriso(1), -graft-points).
std::string escaped(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '=' || c == '\\') r.push_back('\\');
    r.push_back(c);
  }
  return r;
}

// "\\DATA\\DAY.VBI;1" -> "/DATA/DAY.VBI": the path inside the image, without the version.
std::string graftPath(const std::string& discPath) {
  std::string r;
  for (char c : discPath) {
    if (c == ';') break;
    r.push_back(c == '\\' ? '/' : c);
  }
  if (r.empty() || r.front() != '/') r.insert(r.begin(), '/');
  return r;
}

// The image's dates: SOURCE_DATE_EPOCH (https://reproducible-builds.org/specs/source-date-epoch/)
// when set, else 2000-01-01 00:00 UTC, the PS2's launch year.
std::time_t imageEpoch() {
  constexpr std::time_t kDefault = 946684800;
  const char* text = std::getenv("SOURCE_DATE_EPOCH");
  if (text == nullptr) return kDefault;
  char* end = nullptr;
  const long long v = std::strtoll(text, &end, 10);
  return end != text && *end == '\0' && v >= 0 ? static_cast<std::time_t>(v) : kDefault;
}

// "YYYYMMDDhhmmsscc" (xorriso(1), --set_all_file_dates) for `t` in UTC.
std::string isoDate(std::time_t t) {
  std::tm utc{};
  gmtime_r(&t, &utc);
  char b[32];
  std::strftime(b, sizeof b, "%Y%m%d%H%M%S00", &utc);
  return b;
}

// Runs argv with stdout and stderr into `log`; returns the exit status (-1: not run or killed).
int run(std::vector<std::string> args, const std::filesystem::path& log) {
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // The child's environment: ours, with SOURCE_DATE_EPOCH fixed unless the caller chose one.
  std::vector<std::string> env;
  for (char** e = environ; *e != nullptr; ++e) env.emplace_back(*e);
  if (std::getenv("SOURCE_DATE_EPOCH") == nullptr)
    env.emplace_back("SOURCE_DATE_EPOCH=" + std::to_string(imageEpoch()));
  std::vector<char*> envp;
  envp.reserve(env.size() + 1);
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool isDChar(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

bool allDChars(std::string_view s) {
  for (char c : s) {
    if (!isDChar(c)) return false;
  }
  return true;
}

}  // namespace

std::string level1PathProblem(const std::string& discPath) {
  std::string path = graftPath(discPath);
  const auto semi = discPath.find(';');
  if (semi != std::string::npos && discPath.substr(semi) != ";1") return "the version must be ;1";
  std::vector<std::string> parts;
  for (std::size_t at = 1; at <= path.size();) {
    const std::size_t next = std::min(path.find('/', at), path.size());
    parts.push_back(path.substr(at, next - at));
    at = next + 1;
  }
  if (parts.size() > 8) return "more than 8 levels of directories";
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& p = parts[i];
    if (p.empty()) return "an empty name";
    const bool leaf = i + 1 == parts.size();
    const auto dot = p.find('.');
    const std::string_view stem = std::string_view(p).substr(0, leaf ? dot : std::string::npos);
    const std::string_view ext = leaf && dot != std::string::npos ? std::string_view(p).substr(dot + 1) : "";
    if (stem.empty() || stem.size() > 8 || !allDChars(stem)) {
      return "'" + p + "': a name has 1 to 8 characters A-Z 0-9 _";
    }
    if (ext.size() > 3 || !allDChars(ext)) return "'" + p + "': an extension has up to 3 characters A-Z 0-9 _";
  }
  return "";
}

void writeIsoImage(const std::filesystem::path& image, const std::vector<IsoEntry>& files,
                   const std::string& volumeId) {
  const std::string name = image.string();
  for (const IsoEntry& f : files) {
    if (const std::string why = level1PathProblem(f.discPath); !why.empty()) {
      throw iop::DiscError(name + ": cannot hold '" + f.discPath + "' as ISO 9660 level 1 names it: " + why);
    }
  }
  const std::filesystem::path dir = image.has_parent_path() ? image.parent_path() : ".";
  streams::removeStaleTemporaries(dir);  // what a killed run left here (streams/temporary_files.hpp)
  const std::filesystem::path tmp = streams::temporarySibling(image);
  const std::filesystem::path log = streams::temporarySibling(dir / (image.filename().string() + ".log"));
  std::vector<std::string> args{"xorriso",
                                "-abort_on",
                                "FAILURE",
                                "-report_about",
                                "FAILURE",
                                "-as",
                                "mkisofs",
                                "--norock",
                                "-quiet",
                                "-V",
                                volumeId,
                                "-o",
                                tmp.string(),
                                "--set_all_file_dates",
                                isoDate(imageEpoch()),
                                "-graft-points"};
  for (const IsoEntry& f : files) args.push_back(escaped(graftPath(f.discPath)) + "=" + escaped(f.hostFile.string()));
  const int status = run(args, log);
  const std::string output = readText(log);
  std::error_code ec;
  std::filesystem::remove(log, ec);
  if (status != 0) {
    std::filesystem::remove(tmp, ec);
    if (status == -1 || status == 127) {
      throw iop::DiscError(name + ": cannot run xorriso to write the disc image: apt-get install xorriso");
    }
    throw iop::DiscError(name + ": xorriso failed (exit " + std::to_string(status) + "): " + output);
  }
  // Read it back: every file must be where its disc path says (level 1 holds 8.3 upper-case names).
  try {
    const IsoDisc disc(tmp.string());
    for (const IsoEntry& f : files) {
      if (!disc.find(f.discPath)) {
        throw iop::DiscError(name + ": '" + f.discPath + "' is not a name ISO 9660 level 1 holds as given (" +
                             "directories and names of up to 8 characters, an extension of up to 3, A-Z 0-9 _)");
      }
    }
  } catch (const iop::DiscError&) {
    std::filesystem::remove(tmp, ec);
    throw;
  }
  std::filesystem::rename(tmp, image, ec);
  if (ec) {
    const std::string why = ec.message();
    std::filesystem::remove(tmp, ec);
    throw iop::DiscError(name + ": cannot write the disc image: " + why);
  }
}

}  // namespace vbim::streams
