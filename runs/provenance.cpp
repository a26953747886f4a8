#include "runs/provenance.hpp"

#include <openssl/evp.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>

#include "runs/error.hpp"

namespace vbim::runs {

namespace {

using DigestContext = std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)>;

DigestContext newContext() {
  DigestContext ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
    throw RunFailure("SHA-256: cannot start a digest");
  return ctx;
}

std::string finish(EVP_MD_CTX* ctx) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(ctx, digest.data(), &length) != 1) throw RunFailure("SHA-256: cannot finish a digest");
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) {
    char two[3];
    std::snprintf(two, sizeof two, "%02x", digest[i]);
    hex += two;
  }
  return hex;
}

}  // namespace

std::string sha256File(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot be read");
  DigestContext ctx = newContext();
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), buffer.size());
    if (in.gcount() > 0) EVP_DigestUpdate(ctx.get(), buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw Error(path.string() + ": read failed");
  return finish(ctx.get());
}

std::string sha256Text(const std::string& bytes) {
  DigestContext ctx = newContext();
  EVP_DigestUpdate(ctx.get(), bytes.data(), bytes.size());
  return finish(ctx.get());
}

json::Value inputJson(const std::filesystem::path& path) {
  return json::object({{"path", path.string()}, {"sha256", sha256File(path)}});
}

json::Value playProvenance(const PlayRequest& r, const player::PlayerOptions& o) {
  json::Value run = json::object({{"vbim_version", VBIM_VERSION}, {"command", "play"}});
  json::Value disc = inputJson(r.disc);
  // A disc the caller names otherwise (the demo's stream, authored under a temporary name and kept
  // as day.vbim in its output): recorded by that name, so two runs give the same stats.json.
  if (!r.discLabel.empty()) disc["path"] = r.discLabel;
  if (!r.file.empty()) disc["file"] = r.file;
  run["disc"] = disc;
  run["config"] = r.config.empty() ? json::Value("defaults") : inputJson(r.config);
  if (!r.faults.empty()) {
    run["faults"] = inputJson(r.faults);
  } else if (!r.faultsText.empty()) {
    run["faults"] = json::object({{"path", "<built-in>"}, {"sha256", sha256Text(r.faultsText)}});
  } else {
    run["faults"] = "none";
  }
  run["seed"] = o.seed;
  run["duration"] = r.duration;
  run["policy"] = o.config.gs.catchup;
  json::Value branches = json::Value::array();
  for (const std::string& b : r.branches) branches.push(b);
  run["branches"] = branches;
  return run;
}

}  // namespace vbim::runs
