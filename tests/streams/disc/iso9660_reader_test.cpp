// Our ISO 9660 reader (streams/disc/iso9660_records.hpp, iso9660_tree.hpp) on hand-built sectors:
// every damaged field is refused with a message saying where, loops and deep trees stay bounded, and
// the image on which libiso9660 overflowed a heap buffer now gives a DiscError naming the bad field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "iop/error.hpp"
#include "streams/disc/iso9660_records.hpp"
#include "streams/disc/iso9660_tree.hpp"
#include "streams/disc/iso_disc.hpp"
#include "tests/iop/disc_error_of.hpp"

namespace vbim::streams::iso9660::test {
namespace {

namespace fs = std::filesystem;
using Bytes = std::array<std::uint8_t, iop::kSectorBytes>;

void putLe32(Bytes& s, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void putBe32(Bytes& s, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s[at + i] = static_cast<std::uint8_t>(v >> (8 * (3 - i)));
}
// A both-endian 32-bit field (ECMA-119, 4th edition, section 7.3.3); `be` differs from `v` only to
// build a damaged one.
void putBoth32(Bytes& s, std::size_t at, std::uint32_t v, std::optional<std::uint32_t> be = {}) {
  putLe32(s, at, v);
  putBe32(s, at + 4, be.value_or(v));
}
void putBoth16(Bytes& s, std::size_t at, std::uint16_t v) {
  s[at] = static_cast<std::uint8_t>(v & 0xff);
  s[at + 1] = static_cast<std::uint8_t>(v >> 8);
  s[at + 2] = static_cast<std::uint8_t>(v >> 8);
  s[at + 3] = static_cast<std::uint8_t>(v & 0xff);
}

struct Rec {
  std::string id;
  std::uint32_t extent = 0;
  std::uint32_t bytes = 0;
  std::uint8_t flags = 0;
  std::uint8_t unitSize = 0;
};
constexpr std::uint8_t kDir = 0x02;
constexpr std::uint8_t kMultiExtent = 0x80;

// Writes `r` as a directory record at `at`, padded to an even length (ECMA-119, 4th edition, section
// 9.1.12); returns its length.
std::size_t putRecord(Bytes& s, std::size_t at, const Rec& r) {
  const std::size_t len = 33 + r.id.size() + (r.id.size() % 2 == 0 ? 1 : 0);
  s[at] = static_cast<std::uint8_t>(len);
  putBoth32(s, at + 2, r.extent);
  putBoth32(s, at + 10, r.bytes);
  s[at + 25] = r.flags;
  s[at + 26] = r.unitSize;
  s[at + 28] = 1;  // volume sequence number 1, both-endian
  s[at + 31] = 1;
  s[at + 32] = static_cast<std::uint8_t>(r.id.size());
  for (std::size_t i = 0; i < r.id.size(); ++i) s[at + 33 + i] = static_cast<std::uint8_t>(r.id[i]);
  return len;
}

// A directory sector holding "." and ".." (pointing at `self`, `parent`) and then `entries`.
Bytes directorySector(std::uint32_t self, std::uint32_t parent, const std::vector<Rec>& entries) {
  Bytes s{};
  std::size_t at = putRecord(s, 0, {std::string(1, '\0'), self, 2048, kDir});
  at += putRecord(s, at, {std::string(1, '\1'), parent, 2048, kDir});
  for (const Rec& r : entries) at += putRecord(s, at, r);
  return s;
}

// A volume in memory: sectors by LBA (absent ones read as zeros), the root directory at `rootLba`.
struct Volume {
  std::int64_t sectors = 100;
  std::uint32_t rootLba = 20;
  std::uint32_t rootBytes = 2048;
  std::map<std::int64_t, Bytes> at;

  DirectoryTree tree() const {
    PrimaryVolume v;
    v.sectors = sectors;
    v.root.length = 34;
    v.root.extent = rootLba;
    v.root.bytes = rootBytes;
    v.root.directory = true;
    v.root.identifier = std::string(1, '\0');
    return DirectoryTree(
        [this](std::int64_t lba, iop::SectorSpan out) {
          const auto it = at.find(lba);
          Bytes zero{};
          const Bytes& b = it == at.end() ? zero : it->second;
          std::copy(b.begin(), b.end(), out.begin());
        },
        v);
  }
};

using iop::test::discErrorOf;

std::vector<std::string> paths(const std::vector<iop::DiscFile>& files) {
  std::vector<std::string> r;
  r.reserve(files.size());
  for (const auto& f : files) r.push_back(f.path);
  return r;
}

TEST(Iso9660Record, ReadsEveryField) {
  Bytes s{};
  putRecord(s, 100, {"DAY.PSS;1", 300, 5000, 0});
  const auto r = parseRecord(s, 100, 2048, 20);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->length, 42u);
  EXPECT_EQ(r->extent, 300);
  EXPECT_EQ(r->bytes, 5000);
  EXPECT_EQ(r->sectors(), 3);
  EXPECT_FALSE(r->directory);
  EXPECT_FALSE(r->multiExtent);
  EXPECT_FALSE(r->interleaved);
  EXPECT_EQ(r->identifier, "DAY.PSS;1");
  EXPECT_FALSE(r->selfOrParent());
  // Two blocks of extended attribute record come before the data (ECMA-119, 4th edition, section 9.1.2).
  s[100 + 1] = 2;
  EXPECT_EQ(parseRecord(s, 100, 2048, 20)->extent, 302);
}

TEST(Iso9660Record, ZeroLengthByteMeansTheRestOfTheSectorIsPadding) {
  Bytes s{};
  EXPECT_FALSE(parseRecord(s, 0, 2048, 20).has_value());
  EXPECT_FALSE(parseRecord(s, 1500, 2048, 20).has_value());
}

TEST(Iso9660Record, RefusesARecordShorterThanItsFixedPart) {
  Bytes s{};
  putRecord(s, 0, {"A;1", 30, 10, 0});
  s[0] = 20;
  const std::string m = discErrorOf([&] { parseRecord(s, 0, 2048, 21); });
  EXPECT_NE(m.find("directory record at LBA 21 byte 0: length 20 is shorter than a record's 33-byte fixed part"),
            std::string::npos)
      << m;
}

TEST(Iso9660Record, RefusesAnIdentifierRunningPastTheRecord) {
  Bytes s{};
  putRecord(s, 68, {"A;1", 30, 10, 0});
  s[68 + 32] = 40;  // identifier length 40 in a 36-byte record
  const std::string m = discErrorOf([&] { parseRecord(s, 68, 2048, 22); });
  EXPECT_NE(m.find("LBA 22 byte 68: an identifier of 40 bytes does not fit a record of 36 bytes (expected 1 to 3)"),
            std::string::npos)
      << m;
  s[68 + 32] = 0;  // no identifier at all
  EXPECT_NE(discErrorOf([&] { parseRecord(s, 68, 2048, 22); }).find("an identifier of 0 bytes"), std::string::npos);
}

TEST(Iso9660Record, RefusesARecordCrossingTheSectorOrTheDirectoryEnd) {
  Bytes s{};
  s[2030] = 40;  // 40 bytes from byte 2030 would cross into the next sector
  std::string m = discErrorOf([&] { parseRecord(s, 2030, 2048, 23); });
  EXPECT_NE(m.find("LBA 23 byte 2030: its 40 bytes run past byte 2048"), std::string::npos) << m;
  putRecord(s, 0, {"A;1", 30, 10, 0});
  m = discErrorOf([&] { parseRecord(s, 0, 30, 23); });  // the directory's data ends at byte 30
  EXPECT_NE(m.find("run past byte 30"), std::string::npos) << m;
}

TEST(Iso9660Record, RefusesBothEndianHalvesThatDisagree) {
  Bytes s{};
  putRecord(s, 0, {"A;1", 30, 10, 0});
  putBoth32(s, 2, 30, 31);
  std::string m = discErrorOf([&] { parseRecord(s, 0, 2048, 24); });
  EXPECT_NE(m.find("extent location at LBA 24 byte 2: its little-endian half 30 and big-endian half 31 disagree"),
            std::string::npos)
      << m;
  putBoth32(s, 2, 30);
  putBoth32(s, 10, 10, 0x0a000000);
  m = discErrorOf([&] { parseRecord(s, 0, 2048, 24); });
  EXPECT_NE(m.find("data length at LBA 24 byte 10"), std::string::npos) << m;
}

TEST(Iso9660Record, ExtentMustLieInsideTheVolume) {
  DirectoryRecord r;
  r.extent = 90;
  r.bytes = 10 * 2048LL;
  EXPECT_EQ(extentProblem(r, 100), "");
  r.bytes += 1;  // one byte into sector 100
  EXPECT_EQ(extentProblem(r, 100), "at LBA 90 runs past the end of the volume (100 sectors)");
  // The largest values the 32-bit fields hold: no overflow, still past the end.
  r.extent = 0xffffffffLL + 255;
  r.bytes = 0xffffffffLL;
  EXPECT_NE(extentProblem(r, 100), "");
  r.extent = 0;
  EXPECT_NE(extentProblem(r, 2'097'151), "");  // 4 GiB - 1 bytes need 2,097,152 sectors
  EXPECT_EQ(extentProblem(r, 2'097'152), "");
}

TEST(Iso9660Record, NamesCompareWithoutCaseVersionOrTrailingDot) {
  EXPECT_EQ(nameKey("DAY.PSS;1"), "day.pss");
  EXPECT_EQ(nameKey("day.pss"), "day.pss");
  EXPECT_EQ(nameKey("FILE.;1"), "file");
  EXPECT_EQ(nameKey("FILE."), "file");
  EXPECT_EQ(nameKey("VIDEO"), "video");
}

Bytes primaryDescriptor(std::uint32_t sectors, std::uint16_t blockSize) {
  Bytes s{};
  s[0] = 1;
  std::copy_n("CD001", 5, s.begin() + 1);
  s[6] = 1;
  putBoth32(s, 80, sectors);
  putBoth16(s, 128, blockSize);
  Bytes root{};
  putRecord(root, 0, {std::string(1, '\0'), 20, 2048, kDir});
  std::copy_n(root.begin(), 34, s.begin() + 156);
  return s;
}

TEST(Iso9660Descriptor, ReadsThePrimaryVolumeDescriptor) {
  Bytes s = primaryDescriptor(500, 2048);
  EXPECT_EQ(descriptorKind(s), DescriptorKind::Primary);
  const PrimaryVolume v = parsePrimaryVolume(s, 16);
  EXPECT_EQ(v.sectors, 500);
  EXPECT_EQ(v.root.extent, 20);
  EXPECT_TRUE(v.root.directory);
  s[0] = 255;
  EXPECT_EQ(descriptorKind(s), DescriptorKind::Terminator);
  s[0] = 2;
  EXPECT_EQ(descriptorKind(s), DescriptorKind::Other);
  s[6] = 2;  // version 2 is not this standard's
  EXPECT_EQ(descriptorKind(s), DescriptorKind::NotDescriptor);
  s[6] = 1;
  s[3] = 'X';
  EXPECT_EQ(descriptorKind(s), DescriptorKind::NotDescriptor);
}

TEST(Iso9660Descriptor, RefusesOtherBlockSizesDamagedSizesAndRoots) {
  std::string m = discErrorOf([&] { parsePrimaryVolume(primaryDescriptor(500, 512), 16); });
  EXPECT_NE(m.find("logical block size 512 at LBA 16 byte 128, expected 2048"), std::string::npos) << m;
  Bytes s = primaryDescriptor(500, 2048);
  putBoth32(s, 80, 500, 501);
  m = discErrorOf([&] { parsePrimaryVolume(s, 16); });
  EXPECT_NE(m.find("volume space size at LBA 16 byte 80"), std::string::npos) << m;
  s = primaryDescriptor(500, 2048);
  s[156 + 25] = 0;  // the root is not a directory
  m = discErrorOf([&] { parsePrimaryVolume(s, 16); });
  EXPECT_NE(m.find("root directory record at LBA 16 byte 156: expected a directory record of 34 bytes"),
            std::string::npos)
      << m;
  s = primaryDescriptor(500, 2048);
  s[156] = 0;
  EXPECT_NE(discErrorOf([&] { parsePrimaryVolume(s, 16); }).find("root directory record"), std::string::npos);
}

TEST(Iso9660Tree, ListsFilesDepthFirstAndFindsThemByPath) {
  Volume v;
  v.at[20] = directorySector(20, 20, {{"A.PSS;1", 40, 4096, 0}, {"DATA", 21, 2048, kDir}, {"Z", 45, 1, 0}});
  v.at[21] = directorySector(21, 20, {{"DAY.VBI;1", 50, 10000, 0}, {"FILE.;1", 60, 0, 0}});
  const DirectoryTree t = v.tree();
  EXPECT_EQ(paths(t.files()), (std::vector<std::string>{"\\A.PSS;1", "\\DATA\\DAY.VBI;1", "\\DATA\\FILE.;1", "\\Z;1"}));
  const auto f = t.find("/data/day.vbi", "\\DATA\\DAY.VBI;1");
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->lba, 50);
  EXPECT_EQ(f->bytes, 10000);
  EXPECT_TRUE(t.find("/data/file", "x").has_value());
  EXPECT_TRUE(t.find("/z", "x").has_value());
  EXPECT_FALSE(t.find("/data", "x").has_value());  // a directory, not a file
  EXPECT_FALSE(t.find("/data/night.vbi", "x").has_value());
  EXPECT_FALSE(t.find("/a.pss/day.vbi", "x").has_value());  // a file is no directory
}

TEST(Iso9660Tree, ZeroLengthPaddingContinuesAtTheNextSector) {
  Volume v;
  v.at[20] = directorySector(20, 20, {{"A;1", 40, 10, 0}});  // then zeros to the sector's end
  Bytes second{};
  putRecord(second, 0, {"B;1", 41, 10, 0});
  v.at[21] = second;
  v.rootBytes = 2 * 2048;
  const DirectoryTree t = v.tree();
  EXPECT_EQ(paths(t.files()), (std::vector<std::string>{"\\A;1", "\\B;1"}));
  EXPECT_EQ(t.find("/b", "\\B;1")->lba, 41);
}

TEST(Iso9660Tree, AFileOrDirectoryPastTheVolumeIsAnErrorNamingIt) {
  Volume v;
  v.at[20] = directorySector(20, 20, {{"BIG.PSS;1", 95, 6 * 2048, 0}});
  std::string m = discErrorOf([&] { v.tree().files(); });
  EXPECT_NE(m.find("file '\\BIG.PSS;1' at LBA 95 runs past the end of the volume (100 sectors): damaged image"),
            std::string::npos)
      << m;
  m = discErrorOf([&] { v.tree().find("/big.pss", "\\BIG.PSS;1"); });
  EXPECT_NE(m.find("file '\\BIG.PSS;1' at LBA 95 runs past"), std::string::npos) << m;
  // A directory claiming 4 GiB: refused before anything of it is read.
  v.at[20] = directorySector(20, 20, {{"HUGE", 30, 0xffffffffU, kDir}});
  m = discErrorOf([&] { v.tree().files(); });
  EXPECT_NE(m.find("directory '\\HUGE\\' at LBA 30 runs past the end of the volume"), std::string::npos) << m;
  m = discErrorOf([&] { v.tree().find("/huge/a.pss", "\\HUGE\\A.PSS;1"); });
  EXPECT_NE(m.find("directory '\\HUGE\\' at LBA 30 runs past"), std::string::npos) << m;
}

TEST(Iso9660Tree, ADamagedRecordIsAnErrorSayingWhere) {
  Volume v;
  v.at[20] = directorySector(20, 20, {{"A;1", 40, 10, 0}});
  v.at[20][68] = 12;  // the third record (after "." and "..", 34 bytes each) is 12 bytes long
  const std::string m = discErrorOf([&] { v.tree().files(); });
  EXPECT_NE(m.find("directory record at LBA 20 byte 68: length 12"), std::string::npos) << m;
}

TEST(Iso9660Tree, ADirectoryThatContainsItselfOrIsLinkedTwiceIsListedOnce) {
  Volume v;
  // The root holds itself (LOOP), and two links to D, which holds two links back to the root and
  // two to itself: without a guard the listing would never end.
  v.at[20] = directorySector(
      20, 20, {{"A;1", 40, 10, 0}, {"D1", 21, 2048, kDir}, {"D2", 21, 2048, kDir}, {"LOOP", 20, 2048, kDir}});
  v.at[21] = directorySector(21, 20,
                             {{"B;1", 41, 10, 0},
                              {"R1", 20, 2048, kDir},
                              {"R2", 20, 2048, kDir},
                              {"S1", 21, 2048, kDir},
                              {"S2", 21, 2048, kDir}});
  const DirectoryTree t = v.tree();
  EXPECT_EQ(paths(t.files()), (std::vector<std::string>{"\\A;1", "\\D1\\B;1"}));
  // A path is finite, so find() may follow the links as far as it names them (8 levels at most).
  EXPECT_EQ(t.find("/loop/loop/d2/s1/b", "x")->lba, 41);
  // An overlapping extent counts as visited too: IN starts inside BIG (whose second sector it is),
  // so its records are listed once, as BIG's.
  v.at[20] = directorySector(20, 20, {{"BIG", 21, 3 * 2048, kDir}, {"IN", 22, 2048, kDir}});
  v.at[21] = directorySector(21, 20, {{"B;1", 41, 10, 0}});
  v.at[22] = directorySector(22, 20, {{"C;1", 42, 10, 0}});
  EXPECT_EQ(paths(v.tree().files()), (std::vector<std::string>{"\\BIG\\B;1", "\\BIG\\C;1"}));
}

TEST(Iso9660Tree, FollowsEightLevelsAndNoMore) {
  Volume v;
  // The root (level 1) at LBA 20, L2 at 21, ..., L9 at 28; each holds F;1 and the next level.
  for (std::uint32_t level = 1; level <= 9; ++level) {
    std::vector<Rec> entries{{"F;1", 40 + level, 10, 0}};
    if (level < 9) entries.push_back({"L" + std::to_string(level + 1), 20 + level, 2048, kDir});
    v.at[19 + level] = directorySector(19 + level, level == 1 ? 20 : 18 + level, entries);
  }
  const auto files = paths(v.tree().files());
  ASSERT_EQ(files.size(), 8u);
  EXPECT_EQ(files.back(), "\\L2\\L3\\L4\\L5\\L6\\L7\\L8\\F;1");
  EXPECT_EQ(v.tree().find("/l2/l3/l4/l5/l6/l7/l8/f", "x")->lba, 48);
  EXPECT_FALSE(v.tree().find("/l2/l3/l4/l5/l6/l7/l8/l9/f", "x").has_value());
}

TEST(Iso9660Tree, MultiExtentAndInterleavedFilesAreRefusedByFindAndLeftOutOfTheList) {
  Volume v;
  v.at[20] = directorySector(20, 20,
                             {{"A;1", 40, 10, 0},
                              {"BIG;1", 50, 2048, kMultiExtent},
                              {"BIG;1", 51, 100, 0},
                              {"C;1", 60, 10, 0},
                              {"MIX;1", 70, 4096, 0, 1},
                              {"ODD;1", 80, 10, kMultiExtent},
                              {"Q;1", 81, 10, 0}});
  const DirectoryTree t = v.tree();
  // ODD's flag promises a next part under its name; Q is another file, listed as usual.
  EXPECT_EQ(paths(t.files()), (std::vector<std::string>{"\\A;1", "\\C;1", "\\Q;1"}));
  std::string m = discErrorOf([&] { t.find("/big", "\\BIG;1"); });
  EXPECT_NE(m.find("file '\\BIG;1' is recorded in several extents"), std::string::npos) << m;
  m = discErrorOf([&] { t.find("/mix", "\\MIX;1"); });
  EXPECT_NE(m.find("file '\\MIX;1' is recorded interleaved"), std::string::npos) << m;
}

// An image xorriso wrote, then damaged: the record of \VIDEO\A.PSS;1 says the file is larger than
// the volume. find() and files() name the file; the other file is still found.
TEST(IsoDiscDamaged, AFileRunningPastTheVolumeIsADiscErrorNamingIt) {
  const fs::path d = fs::temp_directory_path() / ("vbim_iso9660_damaged_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d / "root" / "VIDEO");
  std::ofstream(d / "root" / "VIDEO" / "A.PSS") << std::string(5000, 'a');
  std::ofstream(d / "root" / "VIDEO" / "B.PSS") << std::string(5000, 'b');
  const fs::path iso = d / "disc.iso";
  const std::string cmd = "xorriso -abort_on FAILURE -report_about FAILURE -as mkisofs -quiet -o '" + iso.string() +
                          "' '" + (d / "root").string() + "' >/dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << "xorriso failed";
  std::string image;
  {
    std::ifstream in(iso, std::ios::binary);
    image.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::int64_t lba = IsoDisc(iso.string()).find("\\VIDEO\\A.PSS;1")->lba;
  const std::size_t id = image.find("A.PSS;1");
  ASSERT_NE(id, std::string::npos);
  Bytes field{};
  putBoth32(field, 0, 0x40000000U);  // 1 GiB
  std::copy_n(field.begin(), 8, image.begin() + static_cast<std::ptrdiff_t>(id - 33 + 10));
  std::ofstream(iso, std::ios::binary | std::ios::trunc) << image;

  const IsoDisc disc(iso.string());
  const std::string expected = iso.string() + ": file '\\VIDEO\\A.PSS;1' at LBA " + std::to_string(lba) +
                               " runs past the end of the volume (" + std::to_string(disc.sectorCount()) +
                               " sectors): damaged image";
  std::string m = discErrorOf([&] { disc.find("\\VIDEO\\A.PSS;1"); });
  EXPECT_EQ(m, expected);
  m = discErrorOf([&] { disc.files(); });
  EXPECT_EQ(m, expected);
  EXPECT_TRUE(disc.find("/video/b.pss").has_value());
  fs::remove_all(d);
}

// The fuzz finding (tests/fuzz/corpus/iso/): libiso9660 wrote past a heap buffer on this image. Its
// root directory holds a record whose data length reads 4294967040 least significant byte first and
// 4278192128 most significant byte first; our reader stops there with a DiscError saying so, for every
// look-up the fuzzer makes and for the listing.
TEST(IsoDiscFinding, TheImageThatOverflowedLibiso9660GivesADiscError) {
  const fs::path image =
      fs::path(VBIM_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "iso" / "libiso9660_heap_overflow.iso";
  ASSERT_TRUE(fs::exists(image)) << image;
  IsoDisc disc(image.string());
  EXPECT_EQ(disc.sectorCount(), 184);
  const std::string expected = image.string() +
                               ": data length at LBA 18 byte 238: its little-endian half 4294967040 and big-endian "
                               "half 4278192128 disagree";
  for (const char* name : {"\\VIDEO\\DAY.PSS;1", "\\SYSTEM.CNF;1", "\\A\\B\\C.BIN;1"}) {
    const std::string m = discErrorOf([&] { disc.find(name); });
    EXPECT_NE(m.find(expected), std::string::npos) << name << ": " << m;
  }
  const std::string m = discErrorOf([&] { disc.files(); });
  EXPECT_NE(m.find(expected), std::string::npos) << m;
}

}  // namespace
}  // namespace vbim::streams::iso9660::test
