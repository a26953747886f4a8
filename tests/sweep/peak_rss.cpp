// peak_rss OUT PROGRAM [ARGS...]: runs PROGRAM, writes its peak resident set in KiB to OUT, exits
// with its status. Why a separate program: Linux carries a process's peak RSS across exec, and a
// child forked from the test process starts as a copy of it (its RSS counted), so wait4() on a
// child of the test would report at least the test's own size. Forked from this small program,
// the child starts at this program's ~1-2 MB and ru_maxrss is PROGRAM's own peak.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: peak_rss OUT PROGRAM [ARGS...]\n");
    return 2;
  }
  const pid_t pid = fork();
  if (pid < 0) return 125;
  if (pid == 0) {
    execv(argv[2], argv + 2);
    _exit(127);
  }
  int status = 0;
  rusage ru{};
  if (wait4(pid, &status, 0, &ru) != pid) return 125;
  std::FILE* out = std::fopen(argv[1], "w");
  if (out == nullptr) return 125;
  std::fprintf(out, "%ld\n", ru.ru_maxrss);  // KiB on Linux
  std::fclose(out);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 126;
}
