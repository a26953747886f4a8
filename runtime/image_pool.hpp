// Recycled image buffers for decoded pictures. A 512x512 picture is 1 MiB; allocating and zero-
// filling a fresh one for each of them (the IPU writes every byte anyway) cost about 3 % of a play.
// take() hands out an image whose buffer held an earlier picture, or a new empty one; when the last
// holder lets go, the image goes back to the pool (from any thread) and its buffer is kept. Contents
// are stale: only code that overwrites the whole image may take one. The pool's state lives as long
// as any image taken from it, so images may outlive the pool object.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "runtime/image.hpp"

namespace vbim {

class ImagePool {
 public:
  std::shared_ptr<Rgba8Image> take() {
    std::unique_ptr<Rgba8Image> img;
    {
      const std::scoped_lock lock(shelf_->mutex);
      if (!shelf_->free.empty()) {
        img = std::move(shelf_->free.back());
        shelf_->free.pop_back();
      }
    }
    if (!img) img = std::make_unique<Rgba8Image>();
    return std::shared_ptr<Rgba8Image>(img.release(), Return{shelf_});
  }
  // Images waiting to be taken again (tests).
  std::size_t spare() const {
    const std::scoped_lock lock(shelf_->mutex);
    return shelf_->free.size();
  }

 private:
  struct Shelf {
    mutable std::mutex mutex;
    std::vector<std::unique_ptr<Rgba8Image>> free;
  };
  struct Return {
    std::shared_ptr<Shelf> shelf;
    void operator()(Rgba8Image* img) const {
      std::unique_ptr<Rgba8Image> owned(img);
      const std::scoped_lock lock(shelf->mutex);
      shelf->free.push_back(std::move(owned));
    }
  };
  std::shared_ptr<Shelf> shelf_ = std::make_shared<Shelf>();
};

}  // namespace vbim
