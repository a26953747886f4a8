// The thread that writes a run's pictures (player/picture_queue.hpp, issue #31): every picture
// written, in order, with the texels it had when pushed; at most `capacity` waiting; the first
// failure thrown again on the simulation's side and nothing written after it; destruction drops
// what has not started and writes nothing afterwards.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <future>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "player/picture_queue.hpp"

namespace vbim::player {
namespace {

Rgba8Image texels(std::uint8_t value) {
  Rgba8Image img(4, 2);
  for (auto& b : img.pixels) b = value;
  return img;
}

// Holds the writer at its first picture until open() is called.
class Gate {
 public:
  void wait() {
    std::unique_lock<std::mutex> lock(mu_);
    cv_.wait(lock, [this] { return open_; });
  }
  void open() {
    {
      const std::lock_guard<std::mutex> lock(mu_);
      open_ = true;
    }
    cv_.notify_all();
  }

 private:
  std::mutex mu_;
  std::condition_variable cv_;
  bool open_ = false;
};

TEST(PictureQueue, WritesEveryPictureInOrderAsItWasPushed) {
  std::vector<std::string> written;  // only the writer thread touches it until drain() returns
  PictureQueue q(
      [&](const std::filesystem::path& p, Rgba8Image& img) {
        written.push_back(p.string() + "=" + std::to_string(img.pixels[0]));
        img.pixels[0] = 0;  // the writer may change its copy
      },
      2);
  Rgba8Image source = texels(1);
  for (int i = 0; i < 50; ++i) {
    source.pixels[0] = static_cast<std::uint8_t>(i);
    q.push("p" + std::to_string(i), source);  // copied: changing the source afterwards changes nothing
  }
  q.drain();
  ASSERT_EQ(written.size(), 50u);
  for (int i = 0; i < 50; ++i)
    EXPECT_EQ(written[static_cast<std::size_t>(i)], "p" + std::to_string(i) + "=" + std::to_string(i));
  EXPECT_GE(q.cpuSeconds(), 0.0);
}

TEST(PictureQueue, AtMostCapacityWait) {
  Gate gate;
  std::atomic<int> written{0};
  PictureQueue q(
      [&](const std::filesystem::path&, Rgba8Image&) {
        gate.wait();
        ++written;
      },
      3);
  q.push("a", texels(1));  // taken by the writer, which is then held at the gate
  // Three more fit (the third waits, if need be, until the writer has taken "a"); a fifth cannot
  // while the writer is held.
  for (int i = 0; i < 3; ++i) q.push("w" + std::to_string(i), texels(2));
  auto blocked = std::async(std::launch::async, [&] { q.push("over", texels(3)); });
  EXPECT_EQ(blocked.wait_for(std::chrono::milliseconds(200)), std::future_status::timeout);
  EXPECT_EQ(written.load(), 0);
  gate.open();
  blocked.get();
  q.drain();
  EXPECT_EQ(written.load(), 5);
}

TEST(PictureQueue, TheFirstFailureComesBackAndStopsTheWriting) {
  std::vector<std::string> written;
  PictureQueue q(
      [&](const std::filesystem::path& p, Rgba8Image&) {
        if (p == "bad") throw std::runtime_error("bad: cannot write the PNG: No space left on device");
        written.push_back(p.string());
      },
      8);
  q.push("good", texels(1));
  q.push("bad", texels(1));
  try {
    q.drain();
    ADD_FAILURE() << "drain() did not throw";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "bad: cannot write the PNG: No space left on device");
  }
  EXPECT_THROW(q.push("after", texels(1)), std::runtime_error);
  EXPECT_THROW(q.drain(), std::runtime_error);
  EXPECT_EQ(written, std::vector<std::string>{"good"});
}

TEST(PictureQueue, DestructionDropsWhatHasNotStartedAndWritesNothingAfter) {
  Gate gate;
  std::atomic<int> started{0};
  std::atomic<int> written{0};
  {
    std::future<void> opener;  // declared first: destroyed after the queue, so the queue is destroyed held
    PictureQueue q(
        [&](const std::filesystem::path&, Rgba8Image&) {
          ++started;
          gate.wait();
          ++written;
        },
        8);
    for (int i = 0; i < 5; ++i) q.push("p", texels(1));
    while (started.load() == 0) std::this_thread::yield();
    opener = std::async(std::launch::async, [&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      gate.open();
    });
    // The destructor waits for the picture being written (the gate opens), drops the other four.
  }
  EXPECT_EQ(started.load(), 1);
  EXPECT_EQ(written.load(), 1);
}

}  // namespace
}  // namespace vbim::player
