#include "compare/golden.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>

#include "core/error.h"
#include "core/fs.h"
#include "core/json_reader.h"
#include "core/path_component.h"
#include "core/replace_directory.h"
#include "core/sha256.h"

namespace raygate {
namespace {

using nlohmann::json;

constexpr const char* kManifestName = "manifest.json";

GoldenNoise read_noise(const json& j, const std::string& where) {
  GoldenNoise noise;
  noise.runs = j.at("runs").get<int>();
  noise.variance_file = j.at("variance").get<std::string>();
  noise.variance_sha256 = j.at("variance_sha256").get<std::string>();
  checked_component(noise.variance_file, where + ".noise.variance");
  for (const json& s : j.at("inflation")) {
    noise.inflation.push_back({s.at("tile_px").get<int>(), s.at("factor").get<double>()});
  }
  if (noise.runs < 2) throw UsageError(where + ".noise.runs: must be at least 2");
  return noise;
}

json write_noise(const GoldenNoise& noise) {
  json inflation = json::array();
  for (const ScaleInflation& s : noise.inflation) {
    inflation.push_back({{"tile_px", s.tile_px}, {"factor", s.factor}});
  }
  return {{"runs", noise.runs},
          {"variance", noise.variance_file},
          {"variance_sha256", noise.variance_sha256},
          {"inflation", inflation}};
}

// An inflation factor beyond this is no sampler's: a tile's mean varying 1e8 times more than its
// pixels say is more than the pixels of any image a tracer writes could make it.
constexpr double kMaxInflation = 1e8;
constexpr int kMaxGoldenRuns = 1'000'000;

std::string short_hash(const std::string& hash) {
  return hash.empty() ? std::string("(none)") : hash.substr(0, 16) + (hash.size() > 16 ? "…" : "");
}

}  // namespace

std::optional<std::string> golden_file_problem(const std::filesystem::path& golden_dir,
                                               const std::string& file, const std::string& sha256) {
  const std::filesystem::path path = golden_dir / file;
  std::string actual;
  try {
    actual = sha256_file_hex(path);
  } catch (const Error& e) {
    return std::string("golden file cannot be read: ") + e.what();
  }
  if (actual == sha256) return std::nullopt;
  return path.string() + ": its SHA-256 " + short_hash(actual) + " is not the manifest's " +
         short_hash(sha256) + " (" + (golden_dir / "manifest.json").string() +
         "): the golden was changed after it was blessed, so it cannot judge anything; restore "
         "it, or bless it again after looking at it";
}

std::optional<std::string> golden_noise_problem(const GoldenNoise& noise,
                                                const std::string& where) {
  if (noise.runs < 2 || noise.runs > kMaxGoldenRuns) {
    return fmt::format("{}: noise.runs {} is not a number of runs (2 to {})", where, noise.runs,
                       kMaxGoldenRuns);
  }
  for (const ScaleInflation& s : noise.inflation) {
    if (!(s.factor >= 1.0 && s.factor <= kMaxInflation)) {
      return fmt::format(
          "{}: noise.inflation factor {} for tile_px {} must lie in [1, {:g}]: "
          "with it no comparison could ever fail",
          where, s.factor, s.tile_px, kMaxInflation);
    }
  }
  return std::nullopt;
}

const GoldenEntry* GoldenManifest::find(const std::string& id) const {
  for (const GoldenEntry& e : entries) {
    if (e.id == id) return &e;
  }
  return nullptr;
}

void GoldenManifest::upsert(const GoldenEntry& entry) {
  for (GoldenEntry& e : entries) {
    if (e.id == entry.id) {
      e = entry;
      return;
    }
  }
  entries.push_back(entry);
}

GoldenManifest load_golden_manifest(const std::filesystem::path& golden_dir) {
  const std::filesystem::path path = golden_dir / kManifestName;
  GoldenManifest manifest;
  if (!std::filesystem::exists(path)) return manifest;
  try {
    const json doc = read_json_file(path);  // duplicate keys refused (core/json_reader.h)
    if (doc.at("schema_version").get<int>() != GoldenManifest::kSchemaVersion) {
      throw UsageError(path.string() + ": schema_version " +
                       std::to_string(doc.at("schema_version").get<int>()) +
                       " is not supported (expected " +
                       std::to_string(GoldenManifest::kSchemaVersion) + ")");
    }
    manifest.suite = doc.at("suite").get<std::string>();
    manifest.baseline_version = doc.at("baseline").at("version").get<std::string>();
    manifest.baseline_source_sha256 = doc.at("baseline").at("source_sha256").get<std::string>();
    for (const json& e : doc.at("images")) {
      manifest.entries.push_back({e.at("id"), e.at("scene"), e.at("size"), e.at("width"),
                                  e.at("height"), e.at("sampling"), e.at("accel"), e.at("file"),
                                  e.at("sha256")});
      // The file is read, compared and overwritten by bless: it must stay in the golden folder.
      const std::string where =
          path.string() + ": $.images[" + std::to_string(manifest.entries.size() - 1) + "]";
      checked_component(manifest.entries.back().id, where + ".id");
      checked_component(manifest.entries.back().file, where + ".file");
      if (e.contains("noise")) manifest.noise[e.at("id")] = read_noise(e.at("noise"), where);
    }
    if (doc.contains("shared_with")) {
      manifest.shared_with = doc.at("shared_with").get<std::vector<std::string>>();
    }
    if (doc.contains("tracer")) {
      const json& t = doc.at("tracer");
      manifest.tracer =
          GoldenProvenance{t.at("adapter"), t.at("adapter_sha256"), t.at("revision"),  t.at("sha"),
                           t.at("dirty"),   t.at("results"),        t.at("started_at")};
    }
  } catch (const json::exception& e) {
    throw UsageError(path.string() + ": malformed golden manifest: " + e.what());
  }
  return manifest;
}

void save_golden_manifest(const GoldenManifest& manifest, const std::filesystem::path& golden_dir) {
  std::vector<GoldenEntry> entries = manifest.entries;
  std::sort(entries.begin(), entries.end(),
            [](const GoldenEntry& a, const GoldenEntry& b) { return a.id < b.id; });
  json images = json::array();
  for (const GoldenEntry& e : entries) {
    images.push_back({{"id", e.id},
                      {"scene", e.scene},
                      {"size", e.size},
                      {"width", e.width},
                      {"height", e.height},
                      {"sampling", e.sampling},
                      {"accel", e.accel},
                      {"file", e.file},
                      {"sha256", e.sha256}});
    if (const auto noise = manifest.noise.find(e.id); noise != manifest.noise.end()) {
      images.back()["noise"] = write_noise(noise->second);
    }
  }
  json doc = {{"schema_version", GoldenManifest::kSchemaVersion},
              {"suite", manifest.suite},
              {"baseline",
               {{"version", manifest.baseline_version},
                {"source_sha256", manifest.baseline_source_sha256}}},
              {"images", images}};
  if (!manifest.shared_with.empty()) doc["shared_with"] = manifest.shared_with;
  if (manifest.tracer) {
    const GoldenProvenance& t = *manifest.tracer;
    doc["tracer"] = {{"adapter", t.adapter},      {"adapter_sha256", t.adapter_hash},
                     {"revision", t.revision},    {"sha", t.sha},
                     {"dirty", t.dirty},          {"results", t.results},
                     {"started_at", t.started_at}};
  }
  write_file_atomically(golden_dir / kManifestName, doc.dump(2) + "\n");
}

std::filesystem::path adapter_golden_dir(const std::filesystem::path& golden_root,
                                         const std::string& adapter) {
  const std::filesystem::path own = golden_root / adapter;
  if (std::filesystem::exists(own / kManifestName)) return own;
  std::error_code ec;
  std::vector<std::filesystem::path> sets;
  for (const auto& item : std::filesystem::directory_iterator(golden_root, ec)) {
    if (is_replacement_temporary(item.path())) continue;  // a bless half done (or killed)
    if (std::filesystem::exists(item.path() / kManifestName)) sets.push_back(item.path());
  }
  std::sort(sets.begin(), sets.end());  // the same answer on every file system
  for (const std::filesystem::path& set : sets) {
    const std::vector<std::string> shared = load_golden_manifest(set).shared_with;
    if (std::find(shared.begin(), shared.end(), adapter) != shared.end()) return set;
  }
  return own;
}

std::string golden_owner(const GoldenManifest& manifest) {
  if (manifest.entries.empty()) return "none";
  return manifest.tracer ? manifest.tracer->adapter : kBaselineGoldens;
}

}  // namespace raygate
