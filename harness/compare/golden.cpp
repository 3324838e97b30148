#include "compare/golden.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string_view>

#include "core/error.h"
#include "core/fs.h"
#include "core/json_field.h"
#include "core/json_reader.h"
#include "core/path_component.h"
#include "core/replace_directory.h"
#include "core/sha256.h"

namespace raygate {
namespace {

using nlohmann::json;

constexpr const char* kManifestName = "manifest.json";

// Past any image a tracer writes (results documents take the same bound).
constexpr std::int64_t kMaxSide = std::int64_t{1} << 20;
// Far past any SPD generator's largest size; 0 is the generator's default.
constexpr std::int64_t kMaxSceneSize = 1'000'000;

// An int field of an entry: whole and within [lowest, highest], so never wrapped or truncated.
int whole_int(const JsonField& field, std::int64_t lowest, std::int64_t highest) {
  return static_cast<int>(field.as_whole(lowest, highest));
}

std::vector<ScaleInflation> read_inflation(const JsonField& field) {
  std::vector<ScaleInflation> inflation;
  for (const JsonField& scale : field.elements()) {
    scale.expect_object({"tile_px", "factor"});
    const JsonField tile = scale.member("tile_px");
    const int tile_px = whole_int(tile, 0, kMaxSide);  // 0: the whole image
    for (const ScaleInflation& seen : inflation) {
      if (seen.tile_px == tile_px) tile.fail(fmt::format("a second entry for tile_px {}", tile_px));
    }
    // The factor's sense (>= 1, not absurd) is golden_noise_problem's: a check error.
    inflation.push_back({tile_px, scale.member("factor").as_number()});
  }
  return inflation;
}

// A hash as bless writes it, 64 lowercase hex digits: any other text is a manifest edited by
// hand (exit 2, its JSON path), not a golden changed after it was blessed (exit 3).
std::string sha256_at(const JsonField& field) {
  std::string text = field.as_string();
  const bool hex = text.size() == 64 && std::all_of(text.begin(), text.end(), [](char c) {
                     return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
                   });
  if (!hex) {
    field.fail("expected a sha256 as bless writes it: 64 lowercase hex digits, found \"" +
               text.substr(0, 80) + "\"");
  }
  return text;
}

GoldenNoise read_noise(const JsonField& field, const std::string& file) {
  field.expect_object({"runs", "variance", "variance_sha256", "inflation"});
  GoldenNoise noise;
  // Any whole number: a count outside 2 to 10^6 is a golden that cannot judge, a check error
  // like the noise's other nonsense (golden_noise_problem), whichever side it is out on.
  noise.runs = field.member("runs").as_whole(std::numeric_limits<std::int64_t>::min(),
                                             std::numeric_limits<std::int64_t>::max());
  const JsonField variance = field.member("variance");
  noise.variance_file = checked_component(variance.as_string(), file + ": " + variance.path());
  noise.variance_sha256 = sha256_at(field.member("variance_sha256"));
  noise.inflation = read_inflation(field.member("inflation"));
  return noise;
}

// One of the words bless writes, or "" (a tracer's golden, whose sampling is its own): another
// word is an edit, said here with its path, not found later as a golden that cannot judge.
std::string word_of(const JsonField& field, std::initializer_list<std::string_view> words) {
  const std::string word = field.as_string();
  if (word.empty() || std::find(words.begin(), words.end(), word) != words.end()) return word;
  std::string known;
  for (const std::string_view w : words) known += (known.empty() ? "" : ", ") + std::string(w);
  field.fail(fmt::format("unknown value \"{}\" (bless writes {})", word.substr(0, 40), known));
}

// The file is read, compared and overwritten by bless: it must stay in the golden folder.
GoldenEntry read_entry(const JsonField& field, const std::string& file) {
  field.expect_object(
      {"id", "scene", "size", "width", "height", "sampling", "accel", "file", "sha256", "noise"});
  const JsonField id = field.member("id");
  const JsonField image = field.member("file");
  return {checked_component(id.as_string(), file + ": " + id.path()),
          field.member("scene").as_string(),
          whole_int(field.member("size"), 0, kMaxSceneSize),
          whole_int(field.member("width"), 1, kMaxSide),
          whole_int(field.member("height"), 1, kMaxSide),
          word_of(field.member("sampling"), {"center", "corners"}),
          word_of(field.member("accel"), {"none", "bbox"}),
          checked_component(image.as_string(), file + ": " + image.path()),
          sha256_at(field.member("sha256"))};
}

// One entry per id: find() would take the first and noise the last, mixing two goldens.
void read_images(const JsonField& images, const std::string& file, GoldenManifest& manifest) {
  for (const JsonField& field : images.elements()) {
    GoldenEntry entry = read_entry(field, file);
    if (manifest.find(entry.id) != nullptr) {
      field.member("id").fail("duplicate id \"" + entry.id + "\"");
    }
    if (field.has("noise")) manifest.noise[entry.id] = read_noise(field.member("noise"), file);
    manifest.entries.push_back(std::move(entry));
  }
}

GoldenProvenance read_provenance(const JsonField& t) {
  t.expect_object(
      {"adapter", "adapter_sha256", "revision", "sha", "dirty", "results", "started_at"});
  return {t.member("adapter").as_string(),   t.member("adapter_sha256").as_string(),
          t.member("revision").as_string(),  t.member("sha").as_string(),
          t.member("dirty").as_bool(),       t.member("results").as_string(),
          t.member("started_at").as_string()};
}

GoldenManifest read_manifest(const JsonField& doc, const std::string& file) {
  doc.expect_object({"schema_version", "suite", "baseline", "images", "shared_with", "tracer"});
  const JsonField version = doc.member("schema_version");
  if (version.as_whole(std::numeric_limits<std::int64_t>::min(),
                       std::numeric_limits<std::int64_t>::max()) !=
      GoldenManifest::kSchemaVersion) {
    version.fail(fmt::format("schema_version {} is not supported (expected {})",
                             version.value().dump(), GoldenManifest::kSchemaVersion));
  }
  GoldenManifest manifest;
  manifest.suite = doc.member("suite").as_string();
  const JsonField baseline = doc.member("baseline");
  baseline.expect_object({"version", "source_sha256"});
  manifest.baseline_version = baseline.member("version").as_string();
  manifest.baseline_source_sha256 = baseline.member("source_sha256").as_string();
  read_images(doc.member("images"), file, manifest);
  if (doc.has("shared_with")) {
    for (const JsonField& name : doc.member("shared_with").elements()) {
      manifest.shared_with.push_back(name.as_string());
    }
  }
  if (doc.has("tracer")) manifest.tracer = read_provenance(doc.member("tracer"));
  return manifest;
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
  std::error_code error;  // a symlink loop, a folder: said here, not thrown over the other scenes
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error) return "golden file cannot be read: " + path.string() + ": " + error.message();
  if (!std::filesystem::is_regular_file(status)) {
    return path.string() + " is not a regular file: a golden is an image file (" +
           (golden_dir / "manifest.json").string() + " lists it)";
  }
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
  if (noise.inflation.empty()) {
    return fmt::format(
        "{}: noise.inflation is empty: bless writes a factor for every tile size it judges "
        "(how much more a tile's mean varies than its pixels say); bless the golden again",
        where);
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
  std::error_code ec;
  if (std::filesystem::exists(golden_dir, ec) && !std::filesystem::is_directory(golden_dir, ec)) {
    throw UsageError(golden_dir.string() +
                     " is a file, not a folder: a golden folder holds manifest.json and the "
                     "images it lists");
  }
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory) {
    // A symlink loop, a folder raygate may not enter: the user's folder to fix, said plainly.
    throw UsageError(path.string() + ": cannot be read: " + ec.message());
  }
  if (!std::filesystem::exists(status)) return GoldenManifest{};
  const json doc = read_json_file(path);  // duplicate keys refused (core/json_reader.h)
  try {
    return read_manifest(JsonField(doc, "$"), path.string());
  } catch (const FieldError& e) {
    throw UsageError(path.string() + ": " + e.path() + ": " + e.what());
  }
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
  // The provenance's results path may hold a byte that is not UTF-8: written as U+FFFD.
  write_file_atomically(golden_dir / kManifestName,
                        doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
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
