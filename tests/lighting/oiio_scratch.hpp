// Test support for the lighting generator's file tests: a scratch directory per test process
// (removed when the tests end), and input pictures written with OpenImageIO, so the files the
// code under test reads are not made by that code.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <OpenImageIO/imageio.h>

namespace vbim::lighting::testing {

inline std::filesystem::path scratchDir() {
  return std::filesystem::temp_directory_path() / ("vbim_lighting_test_" + std::to_string(::getpid()));
}

inline std::filesystem::path scratch(const std::string& name) {
  std::filesystem::create_directories(scratchDir());
  return scratchDir() / name;
}

class RemoveScratch : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(scratchDir(), ec);
  }
};

template <typename T>
void writeRaw(const std::filesystem::path& path, int w, int h, int channels, OIIO::TypeDesc type,
              const std::vector<T>& data) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(w, h, channels, type)));
  ASSERT_TRUE(out->write_image(type, data.data()));
  ASSERT_TRUE(out->close());
}

}  // namespace vbim::lighting::testing
