// Decoded-picture buffers come back to the pool when their last holder lets go, from any thread,
// and may outlive the pool object itself.
#include "runtime/image_pool.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace vbim {
namespace {

TEST(ImagePool, ReturnsABufferWhenItsLastHolderLetsGo) {
  ImagePool pool;
  std::shared_ptr<Rgba8Image> a = pool.take();
  EXPECT_EQ(a->width, 0);  // a new image is empty
  *a = Rgba8Image(64, 32);
  const std::uint8_t* buffer = a->pixels.data();
  std::shared_ptr<Rgba8Image> holder = a;
  a.reset();
  EXPECT_EQ(pool.spare(), 0u);  // still held
  const std::shared_ptr<Rgba8Image> other = pool.take();
  EXPECT_NE(other.get(), holder.get());
  holder.reset();
  EXPECT_EQ(pool.spare(), 1u);
  const std::shared_ptr<Rgba8Image> again = pool.take();
  EXPECT_EQ(again->width, 64);
  EXPECT_EQ(again->pixels.data(), buffer);  // the same bytes, not a fresh allocation
  EXPECT_EQ(pool.spare(), 0u);
}

TEST(ImagePool, ImagesMayOutliveThePoolAndReturnFromOtherThreads) {
  std::shared_ptr<Rgba8Image> kept;
  {
    ImagePool pool;
    kept = pool.take();
    *kept = Rgba8Image(8, 8);
    std::shared_ptr<Rgba8Image> elsewhere = pool.take();
    std::thread([img = std::move(elsewhere)]() mutable { img.reset(); }).join();
    EXPECT_EQ(pool.spare(), 1u);
  }
  kept.reset();  // the pool object is gone; its shelf is not (ASan checks this)
}

}  // namespace
}  // namespace vbim
