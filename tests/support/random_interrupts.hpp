// Test support: runs of a program stopped by SIGINT or SIGTERM at random moments (issue #33: Ctrl-C
// or SIGTERM at any moment ends a command complete or stopped, nothing left behind), four at a time.
//
// Run i is `program` with the arguments the bash function body `argsOf` prints for $1 (of kind
// i % kinds), writing its output at $D/r<i> (a directory, or a file such as r<i>.vbim); its
// stdout and stderr go to dir/log<i>. Run i is sent SIGINT, or SIGTERM when (i / kinds) is odd, so
// that every kind meets both signals. The launching shell ignores both signals itself before it
// starts each run in the background, so the run inherits them ignored from the fork on, as a
// background job of a script does with SIGINT: a signal that comes before the program's handlers are
// in is lost and the run completes. (Starting each run as `(trap '' INT; exec ...) &` left SIGINT at
// the shell's default until the subshell had run its trap: on a loaded machine a signal sent in the
// first milliseconds ended the subshell itself, exit 130 with no message, the test's flake.) The
// moments are spread over 1.2 times each kind's own time, measured uninterrupted by the same script
// with four at a time (runs 900, 900 + kinds, ...; their outputs removed), so that on a loaded
// machine as on an idle one they reach from before the handlers are in to after the output is
// complete.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/run_command.hpp"

namespace vbim::testing {

struct InterruptedRun {
  int index = 0;
  int status = 0;     // the exit status
  bool term = false;  // sent SIGTERM (else SIGINT)
  std::string log;    // its stdout and stderr
};

// The runs in the order they ended; empty, with a test failure, when the script itself failed (a
// kind that fails uninterrupted).
inline std::vector<InterruptedRun> runWithRandomInterrupts(const std::filesystem::path& dir, const std::string& program,
                                                           const std::string& argsOf, int kinds, int runs) {
  const std::string k = std::to_string(kinds);
  const std::string script = "export D VBIM\nargs_of() {\n" + argsOf + R"(
}
ms() { echo $(( $(date +%s%N) / 1000000 )); }
for k in $(seq 0 $((KINDS - 1))); do
  t0=$(ms)
  for j in 0 1 2 3; do $VBIM $(args_of $((900 + k + j * KINDS))) >/dev/null 2>&1 & done
  for j in 0 1 2 3; do wait -n || { echo "kind $k failed uninterrupted"; exit 1; }; done
  echo $(( $(ms) - t0 )) >$D/time$k
  rm -rf $D/r9*
done
one() {
  i=$1
  sig=INT; [ $((i / KINDS % 2)) -eq 1 ] && sig=TERM
  trap '' INT TERM
  $VBIM $(args_of $i) >$D/log$i 2>&1 &
  pid=$!
  t=$(cat $D/time$((i % KINDS)))
  delay=$(( (RANDOM * 32768 + RANDOM) % (t * 6 / 5 + 1) ))
  sleep $((delay / 1000)).$(printf '%03d' $((delay % 1000)))
  kill -$sig $pid 2>/dev/null
  wait $pid
  echo "$i $? $sig" >>$D/status
}
export -f one args_of
export KINDS
seq )" + std::to_string(runs) +
                             R"( | xargs -P 4 -I{} bash -c 'one {}'
rm -f $D/time*
)";
  std::ofstream(dir / "interrupt.sh") << script;
  const CommandResult r =
      runCommand("D=" + dir.string() + " KINDS=" + k + " VBIM=" + program + " bash " + (dir / "interrupt.sh").string());
  std::filesystem::remove(dir / "interrupt.sh");
  if (r.status != 0) {
    ADD_FAILURE() << r.output;
    return {};
  }
  std::vector<InterruptedRun> out;
  std::ifstream status(dir / "status");
  InterruptedRun run;
  for (std::string sig; status >> run.index >> run.status >> sig;) {
    run.term = sig == "TERM";
    run.log = readFileBytes(dir / ("log" + std::to_string(run.index)));
    out.push_back(run);
  }
  return out;
}

// A run that did not complete was stopped by its signal: exit 130 (SIGINT) or 143 (SIGTERM), saying so.
inline void expectStoppedCleanly(const InterruptedRun& run) {
  const char* sig = run.term ? "SIGTERM" : "SIGINT";
  EXPECT_EQ(run.status, run.term ? 143 : 130) << "run " << run.index << " (" << sig << ")\n" << run.log;
  const std::string said = run.term ? "stopped by a signal; temporary files removed, outputs left as they were"
                                    : "interrupted (Ctrl-C); temporary files removed, outputs left as they were";
  EXPECT_NE(run.log.find(said), std::string::npos)
      << "run " << run.index << " (" << sig << ", exit " << run.status << ") did not say so:\n"
      << run.log;
}

// Nothing hidden (a temporary output, .NAME.tmp-PID) is left in `dir`.
inline void expectNothingHiddenLeft(const std::filesystem::path& dir) {
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    EXPECT_NE(name[0], '.') << "left behind: " << name;
  }
}

}  // namespace vbim::testing
