// Disc images: bare stream files and ISO 9660 images built at test time with xorriso; files found
// by path as sceCdSearchFile does; bad images rejected with clear messages.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "iop/file_disc.hpp"
#include "iop/sector_file.hpp"
#include "runtime/rng.hpp"
#include "streams/disc/iso_disc.hpp"
#include "tests/iop/disc_error_of.hpp"
#include "tests/iop/iop_fixture.hpp"

namespace vbim::iop::test {
namespace {

namespace fs = std::filesystem;

fs::path tempDir() {
  fs::path d = fs::temp_directory_path() /
               ("vbim_iop_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// A file whose sector k carries the pattern of LBA (tag + k), so a reader can tell the files apart.
void writePatternFile(const fs::path& p, std::int64_t sectors, std::int64_t tag) {
  std::ofstream out(p, std::ios::binary);
  for (std::int64_t k = 0; k < sectors; ++k) {
    for (std::size_t i = 0; i < kSectorBytes; ++i) out.put(static_cast<char>(MemoryDisc::patternByte(tag + k, i)));
  }
}

TEST(FileDisc, HoldsTheStreamAtItsLba) {
  const fs::path d = tempDir();
  writePatternFile(d / "day.pss", 10, 7);
  FileDisc disc((d / "day.pss").string(), 5000);
  EXPECT_EQ(disc.sectorCount(), 5010);
  const auto f = disc.find("\\DAY.PSS;1");
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->lba, 5000);
  EXPECT_EQ(f->sectors(), 10);
  std::array<std::uint8_t, kSectorBytes> buf{};
  ASSERT_TRUE(disc.read(5003, buf).ok);
  EXPECT_TRUE(sectorHasPattern(buf.data(), 10));
  ASSERT_TRUE(disc.read(10, buf).ok);
  EXPECT_EQ(buf[0], 0);  // before the file: nothing recorded
  EXPECT_FALSE(disc.read(5010, buf).ok);
  EXPECT_FALSE(disc.find("NIGHT.PSS").has_value());
  fs::remove_all(d);
}

// The read-ahead window gives the file's bytes wherever a read falls: inside a window, across two,
// larger than one, backwards, at the end, past it.
TEST(SectorFile, ReadsTheSameBytesAsTheFileAtAnyOffsetAndSize) {
  const fs::path d = tempDir();
  std::vector<std::uint8_t> bytes(10 * kSectorBytes + 700);  // a tail shorter than a sector
  Rng rng(11);
  for (auto& b : bytes) b = static_cast<std::uint8_t>(rng.below(256));
  {
    std::ofstream out(d / "f.bin", std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
  SectorFile f(3 * kSectorBytes);
  ASSERT_TRUE(f.open((d / "f.bin").string()));
  for (int round = 0; round < 2000; ++round) {
    const std::size_t size = 1 + rng.below(round % 10 == 0 ? 8 * kSectorBytes : kSectorBytes + 100);
    const std::size_t at = rng.below(bytes.size() + 200);
    std::vector<std::uint8_t> got(size);
    const bool ok = f.read(static_cast<std::int64_t>(at), got);
    ASSERT_EQ(ok, at + size <= bytes.size()) << "at " << at << " size " << size;
    if (ok) {
      ASSERT_TRUE(std::equal(got.begin(), got.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at)))
          << "at " << at << " size " << size;
    }
  }
  std::uint8_t one = 0;
  EXPECT_FALSE(f.read(-1, std::span<std::uint8_t>(&one, 1)));
  EXPECT_FALSE(SectorFile().open((d / "missing.bin").string()));
  fs::remove_all(d);
}

TEST(FileDisc, RejectsMissingEmptyAndTruncatedFiles) {
  const fs::path d = tempDir();
  EXPECT_NE(discErrorOf([&] { FileDisc((d / "nope.pss").string(), 0); }).find("nope.pss: no such stream file"),
            std::string::npos);
  std::ofstream((d / "empty.pss").string()).close();
  EXPECT_NE(discErrorOf([&] { FileDisc((d / "empty.pss").string(), 0); }).find("is empty"), std::string::npos);
  writePatternFile(d / "cut.pss", 3, 0);
  fs::resize_file(d / "cut.pss", 3 * kSectorBytes - 100);
  const std::string m = discErrorOf([&] { FileDisc((d / "cut.pss").string(), 100); });
  EXPECT_NE(m.find("6044 bytes is not a whole number of 2048-byte sectors"), std::string::npos) << m;
  EXPECT_NE(m.find("byte offset 4096, LBA 102"), std::string::npos) << m;
  writePatternFile(d / "ok.pss", 3, 0);
  EXPECT_NE(
      discErrorOf([&] { FileDisc((d / "ok.pss").string(), 10, 12); }).find("ends at LBA 13, beyond the disc's 12"),
      std::string::npos);
  EXPECT_NE(discErrorOf([&] { FileDisc(d.string(), 0); }).find("is a directory"), std::string::npos);
  fs::remove_all(d);
}

// Builds an ISO with two stream files and a filler between them; returns its path.
fs::path buildIso(const fs::path& d, std::int64_t fillerSectors) {
  fs::create_directories(d / "root" / "VIDEO");
  writePatternFile(d / "root" / "VIDEO" / "A.PSS", 200, 1'000'000);
  writePatternFile(d / "root" / "VIDEO" / "B.PSS", 200, 2'000'000);
  writePatternFile(d / "root" / "VIDEO" / "AB_FILL.BIN", fillerSectors, 0);
  fs::path iso = d / "disc.iso";
  const std::string cmd = "xorriso -abort_on FAILURE -report_about FAILURE -as mkisofs -quiet -V VBIM -o '" +
                          iso.string() + "' '" + (d / "root").string() + "' >/dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0) return {};
  return iso;
}

TEST(IsoDisc, FindsFilesByPathAndReadsTheirSectors) {
  const fs::path d = tempDir();
  const fs::path iso = buildIso(d, 64);
  ASSERT_FALSE(iso.empty()) << "xorriso failed";
  streams::IsoDisc disc(iso.string());
  const DiscFile a = requireFile(disc, "\\VIDEO\\A.PSS;1");
  const DiscFile b = requireFile(disc, "/video/b.pss");
  EXPECT_EQ(a.sectors(), 200);
  EXPECT_EQ(b.sectors(), 200);
  EXPECT_NE(a.lba, b.lba);
  std::array<std::uint8_t, kSectorBytes> buf{};
  for (std::int64_t k : {0, 57, 199}) {
    ASSERT_TRUE(disc.read(a.lba + k, buf).ok);
    EXPECT_TRUE(sectorHasPattern(buf.data(), 1'000'000 + k));
    ASSERT_TRUE(disc.read(b.lba + k, buf).ok);
    EXPECT_TRUE(sectorHasPattern(buf.data(), 2'000'000 + k));
  }
  const std::string m = discErrorOf([&] { requireFile(disc, "\\VIDEO\\NIGHT.PSS;1"); });
  EXPECT_NE(m.find(iso.string() + ": no file '\\VIDEO\\NIGHT.PSS;1' on the disc"), std::string::npos) << m;
  fs::remove_all(d);
}

TEST(IsoDisc, RejectsMissingTruncatedAndForeignImages) {
  const fs::path d = tempDir();
  EXPECT_NE(discErrorOf([&] { streams::IsoDisc((d / "none.iso").string()); }).find("none.iso: no such disc image"),
            std::string::npos);
  writePatternFile(d / "junk.iso", 40, 0);
  EXPECT_NE(discErrorOf([&] { streams::IsoDisc((d / "junk.iso").string()); }).find("junk.iso: "), std::string::npos);
  writePatternFile(d / "tiny.iso", 3, 0);
  EXPECT_NE(discErrorOf([&] { streams::IsoDisc((d / "tiny.iso").string()); }).find("too short for ISO 9660"),
            std::string::npos);
  const fs::path iso = buildIso(d, 64);
  ASSERT_FALSE(iso.empty());
  const auto full = fs::file_size(iso);
  fs::resize_file(iso, full - 100 * kSectorBytes);
  const std::string m = discErrorOf([&] { streams::IsoDisc(iso.string()); });
  EXPECT_NE(m.find("truncated"), std::string::npos) << m;
  EXPECT_NE(m.find("first missing sector is LBA " + std::to_string(full / kSectorBytes - 100)), std::string::npos) << m;
  fs::remove_all(d);
}

struct Timed {
  Tick took;
  SeekClass seek;
};

Task<void> readFiles(Scheduler& s, Drive& drive, std::vector<std::pair<std::int64_t, std::int64_t>> reads,
                     std::vector<Timed>& out) {
  Event ev(s);
  for (const auto& [lba, n] : reads) {
    auto c = std::make_shared<DriveCommand>();
    c->lsn = lba;
    c->sectors = n;
    c->notify = &ev;
    drive.enqueue(c);
    while (!c->done) co_await ev.wait();
    out.push_back(Timed{c->finishedAt - c->issuedAt, c->seek});
  }
}

TEST(IsoDisc, ReadingTwoFilesAlternatelyCostsSeeks) {
  const fs::path d = tempDir();
  const fs::path iso = buildIso(d, 2000);
  ASSERT_FALSE(iso.empty());
  streams::IsoDisc disc(iso.string());
  const DiscFile a = requireFile(disc, "\\VIDEO\\A.PSS;1");
  const DiscFile b = requireFile(disc, "\\VIDEO\\B.PSS;1");
  ASSERT_GE(std::abs(a.lba - b.lba), 32);

  auto run = [&](std::vector<std::pair<std::int64_t, std::int64_t>> reads, Tick& total) {
    Scheduler s;
    DriveParams p;
    p.initially_spinning = true;
    Drive drive(s, disc, p, Rng(5));
    std::vector<Timed> out;
    s.spawn("reader", readFiles(s, drive, std::move(reads), out));
    total = s.run();
    return std::make_pair(out, drive.stats());
  };
  std::vector<std::pair<std::int64_t, std::int64_t>> alternate, sequential;
  for (int k = 0; k < 6; ++k) {
    alternate.emplace_back(a.lba + 32LL * k, 32);
    alternate.emplace_back(b.lba + 32LL * k, 32);
  }
  for (int k = 0; k < 6; ++k) sequential.emplace_back(a.lba + 32LL * k, 32);
  for (int k = 0; k < 6; ++k) sequential.emplace_back(b.lba + 32LL * k, 32);
  Tick tAlt = 0, tSeq = 0;
  const auto [alt, altStats] = run(alternate, tAlt);
  const auto [seq, seqStats] = run(sequential, tSeq);
  // Alternating: every switch after the first read is a seek (fast: the files are close).
  EXPECT_EQ(altStats.seeks[static_cast<int>(SeekClass::Fast)] + altStats.seeks[static_cast<int>(SeekClass::Full)], 12);
  // Sequential: the first read and the jump from A to B.
  EXPECT_EQ(seqStats.seeks[static_cast<int>(SeekClass::Fast)] + seqStats.seeks[static_cast<int>(SeekClass::Full)], 2);
  EXPECT_GT(tAlt, tSeq + 10 * fromUs(30'000));
  fs::remove_all(d);
}

}  // namespace
}  // namespace vbim::iop::test
