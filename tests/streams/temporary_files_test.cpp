// Leftover temporaries of dead processes go; those of live processes, and everything else, stay.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "streams/temporary_files.hpp"

namespace fs = std::filesystem;
using vbim::streams::removeStaleTemporaries;
using vbim::streams::temporarySibling;

namespace {

// The PID of a child that has exited and been reaped: no process has it (barring reuse within
// microseconds, which Linux's increasing PID allocation makes practically impossible).
pid_t deadPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

void touch(const fs::path& p) {
  std::ofstream(p) << "x";
}

}  // namespace

TEST(TemporaryFiles, SiblingNamesCarryThisProcess) {
  EXPECT_EQ(temporarySibling("out/run").string(), "out/.run.tmp-" + std::to_string(::getpid()));
  EXPECT_EQ(temporarySibling("day.vbim").string(), "./.day.vbim.tmp-" + std::to_string(::getpid()));
}

TEST(TemporaryFiles, OnlyThoseOfDeadProcessesAreRemoved) {
  const fs::path d = fs::temp_directory_path() / ("vbim_tmpfiles_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  const std::string dead = std::to_string(deadPid());
  const std::string live = std::to_string(::getppid());  // our parent runs while we do
  fs::create_directories(d / (".run.tmp-" + dead) / "frames");
  touch(d / (".run.tmp-" + dead) / "frames" / "a.png");
  touch(d / (".day.vbim.tmp-" + dead));
  fs::create_directories(d / (".run.tmp-" + dead + ".old"));
  touch(d / (".disc.iso.log.tmp-" + dead));
  // kept: a live process's, our own, and names that only look alike
  fs::create_directories(d / (".run.tmp-" + live));
  touch(d / (".mine.tmp-" + std::to_string(::getpid())));
  for (const char* keep : {"run.tmp-1", ".run.tmp-", ".run.tmp-12x", ".run.tmp--5", ".run.tmp-0", "run", ".hidden"}) {
    touch(d / keep);
  }

  EXPECT_EQ(removeStaleTemporaries(d), 4);
  EXPECT_FALSE(fs::exists(d / (".run.tmp-" + dead)));
  EXPECT_FALSE(fs::exists(d / (".day.vbim.tmp-" + dead)));
  EXPECT_FALSE(fs::exists(d / (".run.tmp-" + dead + ".old")));
  EXPECT_FALSE(fs::exists(d / (".disc.iso.log.tmp-" + dead)));
  EXPECT_TRUE(fs::exists(d / (".run.tmp-" + live)));
  EXPECT_TRUE(fs::exists(d / (".mine.tmp-" + std::to_string(::getpid()))));
  int others = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(d)) ++others;
  EXPECT_EQ(others, 2 + 7);
  EXPECT_EQ(removeStaleTemporaries(d / "missing"), 0);  // no such directory: nothing, no throw
  fs::remove_all(d);
}
