// streams/disc/standard_input: standard input is held in a memory file up to a limit, and refused beyond it
// (issue #33: an endless stdin must end with a message, not fill the machine).
#include "streams/disc/standard_input.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <string>
#include <thread>
#include <vector>

namespace {

// A pipe whose write end is fed `bytes` bytes of 'v' by a thread, then closed.
struct FedPipe {
  int fds[2] = {-1, -1};
  std::thread writer;
  explicit FedPipe(std::size_t bytes) {
    EXPECT_EQ(::pipe(fds), 0);
    writer = std::thread([this, bytes] {
      const std::vector<char> data(bytes, 'v');
      std::size_t done = 0;
      while (done < bytes) {
        const ssize_t w = ::write(fds[1], data.data() + done, bytes - done);
        if (w <= 0) break;  // the reader stopped (over the limit): EPIPE
        done += static_cast<std::size_t>(w);
      }
      ::close(fds[1]);
    });
  }
  ~FedPipe() {
    ::close(fds[0]);
    writer.join();
  }
};

TEST(StandardInput, HoldsEveryByteUpToTheLimit) {
  FedPipe pipe(200'000);
  std::string problem;
  const int fd = vbim::streams::copyIntoMemoryFile(pipe.fds[0], 200'000, problem);
  ASSERT_GE(fd, 0) << problem;
  struct stat st {};
  ASSERT_EQ(::fstat(fd, &st), 0);
  EXPECT_EQ(st.st_size, 200'000);
  ::close(fd);
}

TEST(StandardInput, RefusesMoreThanTheLimitWithAMessage) {
  ::signal(SIGPIPE, SIG_IGN);  // the feeding thread writes on after the reader stops
  FedPipe pipe(200'001);
  std::string problem;
  EXPECT_EQ(vbim::streams::copyIntoMemoryFile(pipe.fds[0], 200'000, problem), -1);
  EXPECT_NE(problem.find("<stdin>: more than 200000 bytes"), std::string::npos) << problem;
}

TEST(StandardInput, TheLimitIsADualLayerDvd) {
  EXPECT_EQ(vbim::streams::kStdinLimitBytes, 8'547'991'552ULL);
}

}  // namespace
