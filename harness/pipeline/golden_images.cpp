#include "pipeline/golden_images.h"

#include <OpenImageIO/imagebuf.h>
#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <utility>

#include "compare/image_file.h"
#include "adapter/adapter.h"
#include "compare/golden.h"
#include "compare/image_check.h"
#include "compare/image_compare.h"
#include "compare/noisy_image_check.h"
#include "compare/noisy_image_files.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/path_component.h"
#include "core/paths.h"
#include "core/replace_directory.h"
#include "core/sha256.h"
#include "gate/policy.h"
#include "pipeline/run_images.h"
#include "results/results.h"
#include "runner/scene_files.h"

namespace raygate {

namespace {

// Renders one suite scene with the baseline into the work directory; a failed render is an
// infrastructure failure (the instrument itself broke).
BaselineRender render_scene(const BaselineGoldens& goldens, const SuiteScene& scene) {
  const std::filesystem::path nff = prepare_scene(scene, goldens.work_dir / "scenes");
  BaselineOptions options;
  options.sampling = goldens.suite.sampling;
  BaselineRender render =
      goldens.baseline.render(nff, goldens.work_dir / "renders" / (scene.id + ".png"), options);
  if (!render.process.succeeded()) {
    throw InfraError("raygate-baseline " + render.process.describe() + " on " + nff.string() +
                     "; log: " + render.log.string() + "\n" + log_tail(render.log, 10));
  }
  return render;
}

const SceneResult* find_scene(const ResultsDocument& document, const std::string& id) {
  for (const SceneResult& scene : document.scenes) {
    if (scene.entry.id == id) return &scene;
  }
  return nullptr;
}

// The golden's file is named <id><extension of the run's image>: the extension must be an
// image's, or a crafted document could name the copy "manifest.json" or leave it extension-less.
void checked_image_extension(const std::filesystem::path& image, const std::string& field) {
  std::string extension = image.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* known : {".png", ".ppm", ".pgm", ".pfm", ".exr", ".hdr", ".tga", ".bmp", ".tif",
                            ".tiff", ".jpg", ".jpeg"}) {
    if (extension == known) return;
  }
  throw UsageError(field + ", " + image.string() +
                   ", has no image file extension (.png, .ppm, "
                   ".exr, ...); the golden copy is named after it");
}

// A golden dir takes one suite's goldens of one adapter (or of the baseline).
void check_manifest_suite(const GoldenManifest& manifest, const std::filesystem::path& golden_dir,
                          const std::string& suite) {
  if (!manifest.suite.empty() && manifest.suite != suite) {
    throw UsageError(golden_dir.string() + " holds goldens of suite '" + manifest.suite +
                     "', not '" + suite + "' (use --golden-dir)");
  }
}

void check_manifest_adapter(const GoldenManifest& manifest, const std::filesystem::path& golden_dir,
                            const std::string& adapter) {
  if (manifest.tracer && manifest.tracer->adapter != adapter) {
    throw UsageError(golden_dir.string() + " holds goldens of adapter '" +
                     manifest.tracer->adapter + "', not '" + adapter + "' (use --golden-dir)");
  }
  // A manifest with entries and no tracer is the baseline's: a tracer's images blessed into it
  // would replace the baseline's and mix two tracers in one manifest. Adapters it is shared
  // with (raygate-baseline-bbox) render the baseline's pixels and are judged by them.
  const std::vector<std::string>& shared = manifest.shared_with;
  if (!manifest.tracer && !manifest.entries.empty() &&
      std::find(shared.begin(), shared.end(), adapter) == shared.end()) {
    throw UsageError(golden_dir.string() + " holds the baseline's goldens (raygate golden bless " +
                     "without --from-run), not adapter '" + adapter + "''s (use --golden-dir)");
  }
}

// The revision of the role asked for; the roles the document has when it has not that one (a
// compare's are base and head, a run's is tracer).
const RevisionRecord& revision_of_role(const ResultsDocument& document,
                                       const BlessFromRun& request) {
  if (const RevisionRecord* revision = document.revision(request.role)) return *revision;
  std::string roles;
  for (const RevisionRecord& r : document.revisions) {
    roles += (roles.empty() ? "--role " : " or --role ") + role_name(r.role);
  }
  throw UsageError(
      request.results.string() + " has no revision with role '" + role_name(request.role) + "'" +
      (roles.empty() ? std::string(": it holds no revisions") : " (use " + roles + ")"));
}

using ChosenImages = std::vector<std::pair<const SceneResult*, std::filesystem::path>>;

// Each scene's image of `role`, every one checked before any is blessed.
ChosenImages chosen_images(const ResultsDocument& document, const BlessFromRun& request) {
  const std::string results = request.results.string();
  std::vector<std::string> ids = request.scene_ids;
  if (ids.empty()) {
    for (const SceneResult& scene : document.scenes) ids.push_back(scene.entry.id);
  }
  if (ids.empty()) throw UsageError(results + " holds no scenes");
  ChosenImages chosen;
  for (const std::string& id : ids) {
    const SceneResult* scene = find_scene(document, id);
    if (scene == nullptr) throw UsageError("scene '" + id + "' is not in " + results);
    const RunRecord* run = scene->runs.first_run(request.role);
    if (run == nullptr) {
      throw UsageError(results + ": no successful " + role_name(request.role) + " run of '" + id +
                       "', so no image to bless");
    }
    if (std::error_code unreadable; !std::filesystem::is_regular_file(run->image, unreadable)) {
      const bool there = std::filesystem::exists(run->image, unreadable);
      throw UsageError(results + ": the " + role_name(request.role) + " image of '" + id + "', " +
                       run->image.string() +
                       (there ? ", is not a regular file (a folder, device or FIFO)"
                              : ", is gone (was the run directory removed?)"));
    }
    checked_component(id, results + ": scenes[].entry.id");
    checked_image_extension(
        run->image, results + ": the " + role_name(request.role) + " image of '" + id + "'");
    chosen.emplace_back(scene, run->image);
  }
  return chosen;
}

// One image to become a golden: its file name in the golden folder, where its bytes are now,
// and its manifest entry but for the sha256 (taken from the bytes as written).
struct Blessing {
  std::string file;
  std::filesystem::path image;
  GoldenEntry entry;
  // A Monte Carlo golden: `image` is the runs' mean, this their variance (noise.variance_file).
  std::optional<GoldenNoise> noise;
  std::filesystem::path variance_image;
};

// Fills `fresh` with the new golden set: the old set's files (linked, not copied), each
// blessing's image written over its name (replacing the link, never writing through it), and
// `next` with their entries and the hashes of the bytes as written.
void write_new_set(const std::filesystem::path& golden_dir, const std::filesystem::path& fresh,
                   const std::vector<Blessing>& blessings, GoldenManifest& next) {
  if (std::filesystem::exists(golden_dir)) link_tree(golden_dir, fresh);
  for (const Blessing& b : blessings) {
    write_file_atomically(fresh / b.file, read_file(b.image));
    GoldenEntry entry = b.entry;
    entry.file = b.file;
    entry.sha256 = sha256_file_hex(fresh / b.file);
    next.upsert(entry);
    next.noise.erase(entry.id);
    if (b.noise) {
      GoldenNoise noise = *b.noise;
      write_file_atomically(fresh / noise.variance_file, read_file(b.variance_image));
      noise.variance_sha256 = sha256_file_hex(fresh / noise.variance_file);
      next.noise[entry.id] = std::move(noise);
    }
  }
  save_golden_manifest(next, fresh);
}

// Swaps in the new golden set. Either the old set or the new one is there afterwards, each
// complete and matching its manifest, whatever failed (a full disk, a kill):
// core/replace_directory.h. `manifest` is updated once the new set is in.
void swap_in_goldens(const std::filesystem::path& golden_dir, GoldenManifest& manifest,
                     const std::vector<Blessing>& blessings) {
  for (const Blessing& b : blessings) {  // a link would be replaced: refused, as -o refuses one
    for (const std::string& file : {b.file, b.noise ? b.noise->variance_file : std::string()}) {
      const std::string problem = file.empty() ? "" : symbolic_link_problem(golden_dir / file);
      if (!problem.empty()) throw UsageError("--golden-dir: " + problem);
    }
  }
  GoldenManifest next = manifest;
  try {
    replace_directory(golden_dir, [&](const std::filesystem::path& fresh) {
      write_new_set(golden_dir, fresh, blessings, next);
    });
  } catch (const WriteError& e) {  // named after the golden folder, not its temporary
    throw WriteError(golden_dir, e.reason() + " (writing " + e.path().filename().string() +
                                     "); the goldens there are unchanged");
  }
  manifest = std::move(next);
}

// How the run's tracer made images: as the document records it (settings.images, chosen when
// the run began). A document from before that field: its adapter file's "images", when that
// file is still there and is the adapter the run used (same hash); otherwise deterministic.
ImageKind run_image_kind(const ResultsDocument& document, const RevisionRecord& revision) {
  if (document.settings.images) return *document.settings.images;
  std::error_code ec;
  if (revision.adapter_file.empty() ||
      !std::filesystem::is_regular_file(revision.adapter_file, ec)) {
    return ImageKind::deterministic;
  }
  try {
    const Adapter adapter = load_adapter(revision.adapter_file);
    if (adapter_hash(adapter) == revision.adapter_hash) return adapter.images;
  } catch (const UsageError&) {
  }
  return ImageKind::deterministic;
}

// A golden judges every later image: one holding NaN or infinite values is refused before it is
// written (sweep 12: bless wrote such a mean and variance, which verify then refused).
void refuse_nonfinite(const std::vector<float>& values, int width, const std::string& what) {
  const auto bad =
      std::find_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); });
  if (bad == values.end()) return;
  const auto pixel = static_cast<std::size_t>(bad - values.begin()) / 3;
  const auto columns = static_cast<std::size_t>(std::max(width, 1));
  throw UsageError(fmt::format(
      "{} holds NaN or infinite values (the first at pixel ({}, {})): a golden must be finite; "
      "fix the tracer's images before blessing them",
      what, pixel % columns, pixel / columns));
}

// A Monte Carlo tracer's goldens: per scene the mean and variance of every run's image (each
// rendered with its own seed), written into `stats_dir` before any is blessed.
std::vector<Blessing> monte_carlo_blessings(const ChosenImages& chosen, Role role,
                                            const std::string& sampling,
                                            const std::filesystem::path& stats_dir) {
  std::vector<Blessing> blessings;
  for (const auto& [scene, first_image] : chosen) {
    const SuiteScene& e = scene->entry;
    const std::vector<std::filesystem::path> images = run_images(scene->runs, role);
    if (images.size() < 2) {
      throw UsageError("'" + e.id + "' has " + std::to_string(images.size()) + " " +
                       role_name(role) +
                       " image(s); a Monte Carlo golden needs at least 2 runs with their own "
                       "seeds (run with more rounds: --min-rounds)");
    }
    const NoisyImageStats stats = stats_of_images(images);
    const std::string of = " of the " + role_name(role) + " images of '" + e.id + "'";
    refuse_nonfinite(stats.mean, stats.width, "the mean" + of);
    refuse_nonfinite(stats.variance, stats.width, "the variance" + of);
    const std::string mean_file = e.id + ".mean.exr";
    GoldenNoise noise{stats.runs, e.id + ".variance.exr", {}, stats.inflation};
    write_stats_images(stats, stats_dir / mean_file, stats_dir / noise.variance_file);
    blessings.push_back({mean_file,
                         stats_dir / mean_file,
                         {e.id, e.scene, e.size, stats.width, stats.height, sampling, "", {}, {}},
                         noise,
                         stats_dir / noise.variance_file});
  }
  return blessings;
}

}  // namespace

BaselineGoldens open_baseline_goldens(const std::string& suite_name,
                                      const std::vector<std::string>& scene_ids,
                                      const std::filesystem::path& golden_dir,
                                      const std::filesystem::path& work_dir,
                                      const std::filesystem::path& baseline) {
  const ToolPaths tools = locate_tools(baseline);
  Suite suite = load_suite(suite_name, tools.data_root);
  std::vector<SuiteScene> selected = select_scenes(suite, scene_ids);
  return {std::move(suite), std::move(selected),
          golden_dir.empty() ? tools.data_root / "golden" / kBaselineGoldens : golden_dir,
          std::filesystem::absolute(work_dir),  // "-/scenes/x.nff" read as an option otherwise
          BaselineTool(tools.baseline)};
}

namespace {

// Why the baseline has no golden of `id` to verify against. An image there that the manifest
// does not list is not vouched for (the manifest is the trust anchor): blessing over it would
// replace a picture nobody looked at, so the words say what is missing instead.
// The hint names the suite and the folder as given: `raygate golden bless ID` alone would bless
// the shipped goldens of the ci suite.
std::string missing_golden_text(const BaselineGoldens& goldens, const std::string& id,
                                bool listed) {
  const std::filesystem::path& golden_dir = goldens.golden_dir;
  const std::filesystem::path image = golden_dir / (id + ".png");
  const std::filesystem::path manifest = golden_dir / "manifest.json";
  std::error_code error;
  if (listed || !std::filesystem::exists(image, error)) {
    return fmt::format(
        "no golden image; create it with: raygate golden bless --suite {} "
        "--golden-dir {} {}",
        goldens.suite.path.string(), golden_dir.string(), id);
  }
  return image.string() + " is there, but " +
         (std::filesystem::exists(manifest, error) ? manifest.string() + " has no entry for it"
                                                   : manifest.string() + " is missing") +
         ", so nothing says it is the golden; restore the manifest (from version control), or "
         "look at the image before blessing it again";
}

// Why the golden cannot judge a render, or nullopt: its bytes are not the manifest's, or they
// are but are no image (an error of the check, exit 3, as every other golden check has it).
std::optional<std::string> unusable_golden(const std::filesystem::path& golden_dir,
                                           const GoldenEntry& entry) {
  if (auto problem = golden_file_problem(golden_dir, entry.file, entry.sha256)) return problem;
  if (std::string problem = unreadable_image(golden_dir / entry.file); !problem.empty()) {
    return problem +
           " (the golden; its SHA-256 is the manifest's, so it was blessed so or both "
           "were changed)";
  }
  return std::nullopt;
}

// Where the manifest's entry is not what bless writes for this suite scene (bless of another
// suite, or an edit): a golden of another picture cannot judge this one, though its bytes are
// vouched for. nullopt when it is.
std::optional<std::string> baseline_entry_problem(const BaselineGoldens& goldens,
                                                  const GoldenManifest& manifest,
                                                  const SuiteScene& scene,
                                                  const GoldenEntry& entry) {
  const auto differs = [&](const std::string& what, const auto& said, const auto& suite) {
    return fmt::format(
        "{}: the manifest says {} {}, the suite {} {} (blessed for another suite, "
        "or edited); bless it again after looking at it",
        (goldens.golden_dir / "manifest.json").string(), what, said, what, suite);
  };
  if (entry.scene != scene.scene) return differs("scene", entry.scene, scene.scene);
  if (entry.size != scene.size) return differs("size", entry.size, scene.size);
  if (entry.sampling != goldens.suite.sampling) {
    return differs("sampling", entry.sampling, goldens.suite.sampling);
  }
  if (entry.accel != "none") return differs("accel", entry.accel, "none");
  if (manifest.noise.count(entry.id) > 0) {
    return (goldens.golden_dir / "manifest.json").string() +
           ": a Monte Carlo noise record on the deterministic baseline's golden";
  }
  return std::nullopt;
}

void verify_baseline_scene(const BaselineGoldens& goldens, const GoldenManifest& manifest,
                           const SuiteScene& scene, GoldenVerification& counts,
                           ProgressSink& progress) {
  const GoldenEntry* entry = manifest.find(scene.id);
  std::error_code error;  // one that cannot be looked at (a symlink loop): unusable_golden says
  if (entry == nullptr ||
      (!std::filesystem::exists(goldens.golden_dir / entry->file, error) && !error)) {
    progress.line(fmt::format("MISSING   {:<12} {}", scene.id,
                              missing_golden_text(goldens, scene.id, entry != nullptr)));
    ++counts.missing;
    return;
  }
  const auto unverifiable = [&](const std::string& problem) {
    progress.line(fmt::format("ERROR     {:<12} {}", scene.id, problem));
    ++counts.unverifiable;
  };
  std::optional<std::string> problem = unusable_golden(goldens.golden_dir, *entry);
  if (!problem) problem = baseline_entry_problem(goldens, manifest, scene, *entry);
  if (problem) return unverifiable(*problem);
  const BaselineRender render = render_scene(goldens, scene);
  const int width = render.stats.value("width", 0);
  const int height = render.stats.value("height", 0);
  if (entry->width != width || entry->height != height) {
    return unverifiable(fmt::format("the manifest says {}x{}, the suite renders it at {}x{}",
                                    entry->width, entry->height, width, height));
  }
  const ImageMetrics m = compare_images(render.image, goldens.golden_dir / entry->file, {});
  if (m.expected_width != entry->width || m.expected_height != entry->height) {
    // The manifest describes another image than the one its hash vouches for: both were edited.
    return unverifiable(fmt::format("{} is {}x{}, but the manifest lists it at {}x{}", entry->file,
                                    m.expected_width, m.expected_height, entry->width,
                                    entry->height));
  }
  if (m.identical()) {
    progress.line(fmt::format("ok        {:<12} identical ({:.2f} s)", scene.id,
                              render.process.wall_seconds));
    ++counts.identical;
    return;
  }
  ++counts.different;
  const std::filesystem::path evidence = goldens.work_dir / "evidence";
  write_evidence(render.image, goldens.golden_dir / entry->file, evidence, scene.id);
  progress.line(fmt::format("DIFFERENT {:<12} {}; evidence in {}", scene.id, summarize(m),
                            evidence.string()));
}

}  // namespace

GoldenVerification verify_baseline_goldens(const BaselineGoldens& goldens, ProgressSink& progress) {
  const GoldenManifest manifest = load_golden_manifest(goldens.golden_dir);
  const std::string current_hash = goldens.baseline.source_hash();
  if (!manifest.baseline_source_sha256.empty() && manifest.baseline_source_sha256 != current_hash) {
    progress.line(
        fmt::format("note: goldens were blessed with baseline source {}, this baseline is {}",
                    manifest.baseline_source_sha256.substr(0, 12), current_hash.substr(0, 12)));
  }
  GoldenVerification counts;
  for (const SuiteScene& scene : goldens.selected) {
    verify_baseline_scene(goldens, manifest, scene, counts, progress);
  }
  return counts;
}

void bless_baseline_goldens(const BaselineGoldens& goldens, ProgressSink& progress) {
  GoldenManifest manifest = load_golden_manifest(goldens.golden_dir);
  check_manifest_suite(manifest, goldens.golden_dir, goldens.suite.name);
  if (manifest.tracer) {
    throw UsageError(goldens.golden_dir.string() + " holds " + manifest.tracer->adapter +
                     "'s goldens, blessed from a run; the baseline's belong elsewhere "
                     "(use --golden-dir)");
  }
  manifest.suite = goldens.suite.name;
  manifest.baseline_version = goldens.baseline.version_line();
  manifest.baseline_source_sha256 = goldens.baseline.source_hash();
  // Rendered first, swapped in once: the manifest names one baseline for its whole set, so a
  // swap per scene left a killed bless with some scenes of the old baseline labelled with the new
  // one (a sweep). An interrupted bless leaves the old set; its renders are redone.
  std::vector<Blessing> blessings;
  for (const SuiteScene& scene : goldens.selected) {
    const BaselineRender render = render_scene(goldens, scene);
    const std::string file = scene.id + ".png";
    blessings.push_back({file,
                         render.image,
                         {scene.id,
                          scene.scene,
                          scene.size,
                          render.stats.value("width", 0),
                          render.stats.value("height", 0),
                          goldens.suite.sampling,
                          "none",
                          file,
                          {},
                          {}},
                         std::nullopt,
                         {}});
    progress.line(fmt::format("rendered  {:<12} {} ({:.2f} s)", scene.id, render.image.string(),
                              render.process.wall_seconds));
  }
  swap_in_goldens(goldens.golden_dir, manifest, blessings);
  for (const Blessing& b : blessings) {
    progress.line(
        fmt::format("blessed   {:<12} {}", b.entry.id, (goldens.golden_dir / b.file).string()));
  }
}

namespace {

// The revision whose images become goldens, its adapter name checked: it names a folder.
const RevisionRecord& blessed_revision(const ResultsDocument& document,
                                       const BlessFromRun& request) {
  const std::string results = request.results.string();
  const RevisionRecord& revision = revision_of_role(document, request);
  checked_component(revision.adapter_name,
                    results + ": revisions[" + role_name(request.role) + "].adapter.name");
  return revision;
}

// The manifest says where its goldens came from: this run's baseline, tracer and document.
void record_run_provenance(GoldenManifest& manifest, const ResultsDocument& document,
                           const RevisionRecord& revision, const std::string& results) {
  manifest.suite = document.suite;
  manifest.baseline_version = document.baseline.version;
  manifest.baseline_source_sha256 = document.baseline.source_sha256;
  manifest.tracer =
      GoldenProvenance{revision.adapter_name, revision.adapter_hash,   revision.worktree.revision,
                       revision.worktree.sha, revision.worktree.dirty, results,
                       document.started_at};
}

// A deterministic tracer's goldens: each scene's chosen image as it is. Every image is decoded
// before any is blessed, so one that cannot be read leaves the goldens as they were.
std::vector<Blessing> deterministic_blessings(const ChosenImages& chosen,
                                              const std::string& sampling) {
  std::vector<Blessing> blessings;
  for (const auto& [scene, image] : chosen) {
    const SuiteScene& e = scene->entry;
    OIIO_NAMESPACE::ImageBuf decoded = current_image(image);
    if (!decoded.init_spec(image.string(), 0, 0)) {
      throw UsageError(image.string() + ": cannot read image: " + decoded.geterror());
    }
    const RgbImage pixels = read_rgb_image(image);
    refuse_nonfinite(pixels.rgb, pixels.width, "'" + e.id + "': " + image.string());
    // The hash is provenance only: goldens are compared by decoded pixels, never by bytes.
    blessings.push_back(
        {e.id + image.extension().string(),
         image,
         {e.id, e.scene, e.size, decoded.spec().width, decoded.spec().height, sampling, "", {}, {}},
         std::nullopt,
         {}});
  }
  return blessings;
}

}  // namespace

void bless_goldens_from_run(const BlessFromRun& request, ProgressSink& progress) {
  const ResultsDocument document = read_results(request.results);
  const RevisionRecord& revision = blessed_revision(document, request);
  const std::filesystem::path golden_dir =
      request.golden_dir.empty()
          ? locate_tools(request.baseline).data_root / "golden" / revision.adapter_name
          : request.golden_dir;
  GoldenManifest manifest = load_golden_manifest(golden_dir);
  check_manifest_suite(manifest, golden_dir, document.suite);
  check_manifest_adapter(manifest, golden_dir, revision.adapter_name);
  const ChosenImages chosen = chosen_images(document, request);
  record_run_provenance(manifest, document, revision, request.results.string());
  if (run_image_kind(document, revision) == ImageKind::monte_carlo) {
    const TempDir stats_dir("raygate-bless");
    const std::vector<Blessing> blessings =
        monte_carlo_blessings(chosen, request.role, document.baseline.sampling, stats_dir.path());
    swap_in_goldens(golden_dir, manifest, blessings);
    for (const Blessing& b : blessings) {
      progress.line(fmt::format("blessed   {:<12} {} (mean and variance of {} runs)", b.entry.id,
                                (golden_dir / b.file).string(), b.noise->runs));
    }
    return;
  }
  const std::vector<Blessing> blessings =
      deterministic_blessings(chosen, document.baseline.sampling);
  swap_in_goldens(golden_dir, manifest, blessings);  // one swap for all of them
  for (const Blessing& b : blessings) {
    progress.line(fmt::format("blessed   {:<12} {} (from {})", b.entry.id,
                              (golden_dir / b.file).string(), b.image.string()));
  }
}

namespace {

// One scene's check as a verify line, counted.
void report_check(const std::string& id, const ImageCheck& check, GoldenVerification& counts,
                  ProgressSink& progress) {
  const std::string what = check_detail(check);
  const char* word = "ok       ";
  if (check.verdict == ImageVerdict::missing) {
    word = "MISSING  ";
    ++counts.missing;
  } else if (check.verdict == ImageVerdict::error) {
    word = "ERROR    ";  // the golden could not judge: corrupt, nonsense, unreadable
    ++counts.unverifiable;
  } else if (check.verdict == ImageVerdict::fail) {
    word = "DIFFERENT";
    ++counts.different;
  } else if (check.verdict == ImageVerdict::inconclusive) {
    word = "UNSURE   ";  // a Monte Carlo check too noisy to decide
    ++counts.inconclusive;
  } else {
    ++counts.identical;
  }
  std::string line = fmt::format("{} {:<12} {}", word, id, what);
  if (!check.evidence.empty())
    line += "; evidence in " + check.evidence.front().parent_path().string();
  progress.line(line);
}

}  // namespace

GoldenVerification verify_goldens_from_run(const BlessFromRun& request,
                                           const std::filesystem::path& evidence_dir,
                                           ProgressSink& progress) {
  const ResultsDocument document = read_results(request.results);
  // A scene named that the document does not hold was passed over ("0 scenes", exit 0).
  for (const std::string& id : request.scene_ids) {
    if (find_scene(document, id) == nullptr) {
      throw UsageError("scene '" + id + "' is not in " + request.results.string());
    }
  }
  const RevisionRecord& revision = revision_of_role(document, request);
  const std::filesystem::path golden_dir =
      request.golden_dir.empty()
          ? adapter_golden_dir(locate_tools(request.baseline).data_root / "golden",
                               revision.adapter_name)
          : request.golden_dir;
  const GoldenManifest manifest = load_golden_manifest(golden_dir);
  // As bless refuses them: another suite's goldens, or another tracer's, judge other pictures.
  check_manifest_suite(manifest, golden_dir, document.suite);
  check_manifest_adapter(manifest, golden_dir, revision.adapter_name);
  const ImageKind kind = run_image_kind(document, revision);
  std::string policy_note;
  const GatePolicy policy = recorded_policy(document.settings, policy_note);
  GoldenVerification counts;
  for (const SceneResult& scene : document.scenes) {
    const SuiteScene& e = scene.entry;
    const auto& ids = request.scene_ids;
    if (!ids.empty() && std::find(ids.begin(), ids.end(), e.id) == ids.end()) continue;
    const RunRecord* run = scene.runs.first_run(request.role);
    if (run == nullptr) {
      progress.line(
          fmt::format("MISSING   {:<12} no successful {} run", e.id, to_string(request.role)));
      ++counts.missing;
      continue;
    }
    const GoldenEntry rendered{
        e.id, e.scene, e.size, e.width,       e.height, document.baseline.sampling,
        {},   {},      {},     document.suite};
    const ImageCheck check = kind == ImageKind::monte_carlo
                                 ? check_runs_against_golden(
                                       request.role, run_images(scene.runs, request.role),
                                       golden_dir, manifest, rendered,
                                       noisy_thresholds_for(document.scenes.size(),
                                                            policy.for_scene(e.id).image_tolerance),
                                       evidence_dir)
                                 : check_against_golden(request.role, run->image, golden_dir,
                                                        manifest, rendered, {}, evidence_dir);
    report_check(e.id, check, counts, progress);
  }
  return counts;
}

}  // namespace raygate
