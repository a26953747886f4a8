// streams/authoring/sequence_options: `vbim author`'s sequence options read into image sequences
// (variants in order, each with its sky), and the bad values refused with the option named.
#include "streams/authoring/sequence_options.hpp"

#include <gtest/gtest.h>

#include "streams/authoring/error.hpp"

namespace {

using namespace vbim::streams;

TEST(SequenceOptions, VariantsKeepTheirOrderAndTheirSkies) {
  SequenceOptions o;
  o.name = "clear";
  o.frames = "c/lm_%04d.png";
  o.sky = "c/sky_%04d.png";
  o.variants = {"rain=r/lm_%04d.png", "fog=f/lm_%04d.png"};
  o.variantSkies = {"fog=f/sky_%04d.png", "rain=r/sky_%04d.png"};
  const ImageSequences in = imageSequences(o, InputEncoding::Linear);
  EXPECT_EQ(in.input, InputEncoding::Linear);
  ASSERT_EQ(in.variants.size(), 3u);
  EXPECT_EQ(in.variants[0].name, "clear");
  EXPECT_EQ(in.variants[0].skies, "c/sky_%04d.png");
  EXPECT_EQ(in.variants[1].name, "rain");
  EXPECT_EQ(in.variants[1].lightmaps, "r/lm_%04d.png");
  EXPECT_EQ(in.variants[1].skies, "r/sky_%04d.png");
  EXPECT_EQ(in.variants[2].name, "fog");
  EXPECT_EQ(in.variants[2].skies, "f/sky_%04d.png");
}

TEST(SequenceOptions, BadPairsAndUnknownSkiesAreRefusedByName) {
  SequenceOptions o;
  o.frames = "lm_%04d.png";
  o.variants = {"rain"};
  try {
    imageSequences(o, InputEncoding::Auto);
    FAIL() << "a --variant without NAME=PATTERN was taken";
  } catch (const AuthoringError& e) {
    EXPECT_STREQ(e.what(), "--variant 'rain': expected NAME=PATTERN");
  }
  o.variants = {"rain=r_%04d.png"};
  o.variantSkies = {"snow=s_%04d.png"};
  try {
    imageSequences(o, InputEncoding::Auto);
    FAIL() << "a --variant-sky of no --variant was taken";
  } catch (const AuthoringError& e) {
    EXPECT_STREQ(e.what(), "--variant-sky snow=...: no --variant named 'snow'");
  }
}

TEST(SequenceOptions, InputEncodingsAndWeathers) {
  EXPECT_EQ(inputEncoding("auto"), InputEncoding::Auto);
  EXPECT_EQ(inputEncoding("linear"), InputEncoding::Linear);
  EXPECT_EQ(inputEncoding("encoded"), InputEncoding::Encoded);
  EXPECT_THROW(inputEncoding("srgb"), AuthoringError);
  EXPECT_EQ(weatherList("clear,overcast"), (std::vector<std::string>{"clear", "overcast"}));
  EXPECT_EQ(weatherList("clear"), (std::vector<std::string>{"clear"}));
}

}  // namespace
