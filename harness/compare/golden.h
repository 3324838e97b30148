// Golden images: an adapter's own picture of every suite scene, in golden/<adapter>/, and the
// manifest that says how each was made. The baseline's are golden/raygate-baseline/; they judge
// the baseline and the variants its manifest names (shared_with), never another tracer, whose
// shading differs by design. Goldens change only on request (`golden bless`).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compare/noisy_stats.h"

namespace raygate {

struct GoldenEntry {
  std::string id;  // suite scene id
  std::string scene;
  int size = 0;
  int width = 0;
  int height = 0;
  std::string sampling;
  std::string accel;
  std::string file;    // relative to the golden directory
  std::string sha256;  // of the image file's bytes
  // Set only on the entry describing what a measurement renders (not written in a manifest,
  // which names its suite once): a manifest of that same suite whose entry differs was edited.
  std::string rendering_suite;
};

// A Monte Carlo tracer's golden (docs/monte-carlo-images.md): the entry's file is the per-pixel
// mean of `runs` renders with independent seeds, and this is the rest the comparison needs.
struct GoldenNoise {
  // As the manifest says, however absurd: golden_noise_problem() judges it (2 to 10^6).
  std::int64_t runs = 0;
  std::string variance_file;  // per pixel variance of one run, relative to the golden directory
  std::string variance_sha256;
  std::vector<ScaleInflation> inflation;

  bool operator==(const GoldenNoise&) const = default;
};

// Where a foreign tracer's goldens came from (`golden bless --from-run`): the run that rendered
// them. Absent for the baseline's own goldens, which `golden bless` renders itself.
struct GoldenProvenance {
  std::string adapter;       // adapter name; the goldens live in golden/<adapter>/
  std::string adapter_hash;  // SHA-256 of the adapter document (adapters/README.md)
  std::string revision;      // as asked for ("HEAD", "v1.2", "--worktree PATH")
  std::string sha;           // the commit measured
  bool dirty = false;
  std::string results;     // the results document the images were taken from
  std::string started_at;  // when that run started

  bool operator==(const GoldenProvenance&) const = default;
};

struct GoldenManifest {
  static constexpr int kSchemaVersion = 1;
  std::string suite;
  std::string baseline_version;  // the baseline's --version line when blessed
  std::string baseline_source_sha256;
  std::vector<GoldenEntry> entries;
  std::optional<GoldenProvenance> tracer;  // set for goldens blessed from a run
  // Adapters other than the directory's own that these goldens judge: variants that render the
  // same pictures (the baseline's bbox control).
  std::vector<std::string> shared_with;
  // Monte Carlo goldens' statistics, by entry id ("noise" in the entry's JSON object).
  std::map<std::string, GoldenNoise> noise;

  const GoldenEntry* find(const std::string& id) const;
  void upsert(const GoldenEntry& entry);  // replaces the entry with the same id
};

// The folder of the baseline's goldens under golden/.
inline constexpr const char* kBaselineGoldens = "raygate-baseline";

// Where the goldens that judge `adapter` are, under `golden_root` (<data root>/golden):
// golden/<adapter>/ when it holds a manifest, else the folder whose manifest lists the adapter in
// shared_with, else golden/<adapter>/ all the same (empty or absent: the adapter has no goldens
// yet, and that is where `golden bless --from-run` puts them).
std::filesystem::path adapter_golden_dir(const std::filesystem::path& golden_root,
                                         const std::string& adapter);

// Whose goldens a manifest holds, for the results document's settings.goldens: the adapter it
// was blessed from, kBaselineGoldens for the baseline's, "none" for an empty or absent manifest.
std::string golden_owner(const GoldenManifest& manifest);

// Why the golden file `file` of `golden_dir` cannot be trusted: its bytes' SHA-256 is not
// `sha256`, the manifest's (edited, truncated or swapped since it was blessed), or it cannot be
// read. nullopt when it matches. Every golden file (image, Monte Carlo mean and variance) is
// checked so before it judges anything; a check it fails could not be made (verdict error,
// exit 3), since the trust anchor, not the tracer, is broken.
std::optional<std::string> golden_file_problem(const std::filesystem::path& golden_dir,
                                               const std::string& file, const std::string& sha256);

// Why a Monte Carlo golden's manifest values could never let a comparison fail (an inflation
// factor below 1, not finite or absurdly large; implausibly many runs), naming the manifest
// entry and the value; nullopt when they make sense.
std::optional<std::string> golden_noise_problem(const GoldenNoise& noise, const std::string& where);

// A missing manifest yields an empty one. A malformed one is a UsageError naming the file and
// the JSON path: a wrong type, an unknown key, a duplicate id or inflation scale, a whole number
// out of range. A golden_dir that is a file is a UsageError too.
GoldenManifest load_golden_manifest(const std::filesystem::path& golden_dir);
// Written atomically, entries sorted by id so diffs stay small.
void save_golden_manifest(const GoldenManifest& manifest, const std::filesystem::path& golden_dir);

}  // namespace raygate
