// `raygate golden verify | bless`: the baseline's golden image of every suite scene, in
// golden/raygate-baseline/ (compare/golden.h says whom they judge). verify
// re-renders and demands identical pixels (the baseline is deterministic); bless rewrites goldens
// only for the scenes named (or all), never as a side effect of anything else.
// `bless --from-run RESULTS.json` blesses a foreign tracer's images instead: the ones a run
// already made and checked, copied into golden/<adapter>/ (docs/gate.md).
#include <OpenImageIO/imagebuf.h>
#include <fmt/core.h>

#include <cctype>
#include <memory>

#include "cli/commands.h"
#include "compare/golden.h"
#include "compare/image_compare.h"
#include "core/error.h"
#include "core/path_component.h"
#include "core/paths.h"
#include "core/sha256.h"
#include "runner/baseline_tool.h"
#include "runner/scene_files.h"
#include "runner/suite.h"
#include "results/results.h"

namespace raygate::cli {
namespace {

struct GoldenArgs {
  std::string suite = "ci";
  std::vector<std::string> scenes;
  std::string golden_dir;  // default: <data root>/golden/raygate-baseline (--from-run: /<adapter>)
  std::string work_dir = ".raygate/golden";
  std::string baseline;
  std::string from_run;       // bless: a results document whose tracer images become goldens
  std::string role = "tracer";  // bless --from-run: whose images ("tracer", "head", "base")
};

struct GoldenContext {
  Suite suite;
  std::vector<SuiteScene> selected;
  std::filesystem::path golden_dir;
  std::filesystem::path work_dir;
  BaselineTool baseline;
};

GoldenContext open_context(const GoldenArgs& args) {
  const ToolPaths tools = locate_tools(args.baseline);
  Suite suite = load_suite(args.suite, tools.data_root);
  std::vector<SuiteScene> selected = select_scenes(suite, args.scenes);
  const std::filesystem::path golden_dir = args.golden_dir.empty()
                                               ? tools.data_root / "golden" / kBaselineGoldens
                                               : std::filesystem::path(args.golden_dir);
  return {std::move(suite), std::move(selected), golden_dir, args.work_dir,
          BaselineTool(tools.baseline)};
}

// Renders one suite scene with the baseline into the work directory; a failed render is an
// infrastructure failure (the instrument itself broke).
BaselineRender render_scene(const GoldenContext& ctx, const SuiteScene& scene) {
  const std::filesystem::path nff = prepare_scene(scene, ctx.work_dir / "scenes");
  BaselineOptions options;
  options.sampling = ctx.suite.sampling;
  BaselineRender render = ctx.baseline.render(nff, ctx.work_dir / "renders" / (scene.id + ".png"), options);
  if (!render.process.succeeded()) {
    throw InfraError("raygate-baseline " + render.process.describe() + " on " + nff.string() +
                     "; log: " + render.log.string() + "\n" + log_tail(render.log, 10));
  }
  return render;
}

int run_verify(const GoldenArgs& args) {
  const GoldenContext ctx = open_context(args);
  const GoldenManifest manifest = load_golden_manifest(ctx.golden_dir);
  const std::string current_hash = ctx.baseline.source_hash();
  if (!manifest.baseline_source_sha256.empty() && manifest.baseline_source_sha256 != current_hash) {
    fmt::print("note: goldens were blessed with baseline source {}, this baseline is {}\n",
               manifest.baseline_source_sha256.substr(0, 12), current_hash.substr(0, 12));
  }
  int missing = 0;
  int mismatched = 0;
  for (const SuiteScene& scene : ctx.selected) {
    const GoldenEntry* entry = manifest.find(scene.id);
    if (entry == nullptr || !std::filesystem::exists(ctx.golden_dir / entry->file)) {
      fmt::print("MISSING   {:<12} no golden image; create it with: raygate golden bless {}\n",
                 scene.id, scene.id);
      ++missing;
      continue;
    }
    const BaselineRender render = render_scene(ctx, scene);
    const ImageMetrics m = compare_images(render.image, ctx.golden_dir / entry->file, {});
    if (m.identical()) {
      fmt::print("ok        {:<12} identical ({:.2f} s)\n", scene.id, render.process.wall_seconds);
      continue;
    }
    ++mismatched;
    const std::filesystem::path evidence = ctx.work_dir / "evidence";
    write_evidence(render.image, ctx.golden_dir / entry->file, evidence, scene.id);
    fmt::print("DIFFERENT {:<12} {}; evidence in {}\n", scene.id, summarize(m), evidence.string());
  }
  fmt::print("{} scenes: {} identical, {} different, {} missing\n", ctx.selected.size(),
             ctx.selected.size() - mismatched - missing, mismatched, missing);
  if (missing > 0) return to_int(ExitCode::usage);
  return mismatched > 0 ? to_int(ExitCode::regression) : 0;
}

int run_bless(const GoldenArgs& args) {
  const GoldenContext ctx = open_context(args);
  GoldenManifest manifest = load_golden_manifest(ctx.golden_dir);
  if (!manifest.suite.empty() && manifest.suite != ctx.suite.name) {
    throw UsageError(ctx.golden_dir.string() + " holds goldens of suite '" + manifest.suite +
                     "', not '" + ctx.suite.name + "' (use --golden-dir)");
  }
  if (manifest.tracer) {
    throw UsageError(ctx.golden_dir.string() + " holds " + manifest.tracer->adapter +
                     "'s goldens, blessed from a run; the baseline's belong elsewhere "
                     "(use --golden-dir)");
  }
  manifest.suite = ctx.suite.name;
  manifest.baseline_version = ctx.baseline.version_line();
  manifest.baseline_source_sha256 = ctx.baseline.source_hash();
  for (const SuiteScene& scene : ctx.selected) {
    const BaselineRender render = render_scene(ctx, scene);
    const std::string file = scene.id + ".png";
    std::filesystem::create_directories(ctx.golden_dir);
    std::filesystem::copy_file(render.image, ctx.golden_dir / file,
                               std::filesystem::copy_options::overwrite_existing);
    manifest.upsert({scene.id, scene.scene, scene.size, render.stats.value("width", 0),
                     render.stats.value("height", 0), ctx.suite.sampling, "none", file,
                     sha256_file_hex(ctx.golden_dir / file)});
    save_golden_manifest(manifest, ctx.golden_dir);  // after each scene: an interrupted bless keeps its work
    fmt::print("blessed   {:<12} {} ({:.2f} s)\n", scene.id, (ctx.golden_dir / file).string(),
               render.process.wall_seconds);
  }
  return 0;
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
  for (const char* known : {".png", ".ppm", ".pgm", ".pfm", ".exr", ".hdr", ".tga", ".bmp",
                            ".tif", ".tiff", ".jpg", ".jpeg"}) {
    if (extension == known) return;
  }
  throw UsageError(field + ", " + image.string() + ", has no image file extension (.png, .ppm, "
                   ".exr, ...); the golden copy is named after it");
}

// The foreign tracer's images of a run, as goldens of its adapter. Nothing is rendered: the
// images are the ones the run made (each scene's first successful run of `role`, the image the
// run compared), so what is blessed is exactly what was measured and looked at.
int run_bless_from_run(const GoldenArgs& args) {
  const std::filesystem::path results = std::filesystem::absolute(args.from_run);
  const ResultsDocument document = read_results(results);
  const RevisionRecord* revision = document.revision(args.role);
  if (revision == nullptr) {
    throw UsageError(results.string() + " has no revision with role '" + args.role +
                     "' (use --role tracer, base or head)");
  }
  checked_component(revision->adapter_name,
                    results.string() + ": revisions[" + args.role + "].adapter.name");
  const std::filesystem::path golden_dir =
      args.golden_dir.empty()
          ? locate_tools(args.baseline).data_root / "golden" / revision->adapter_name
          : std::filesystem::path(args.golden_dir);
  std::vector<std::string> ids = args.scenes;
  if (ids.empty()) {
    for (const SceneResult& scene : document.scenes) ids.push_back(scene.entry.id);
  }
  if (ids.empty()) throw UsageError(results.string() + " holds no scenes");

  GoldenManifest manifest = load_golden_manifest(golden_dir);
  if (!manifest.suite.empty() && manifest.suite != document.suite) {
    throw UsageError(golden_dir.string() + " holds goldens of suite '" + manifest.suite +
                     "', not '" + document.suite + "' (use --golden-dir)");
  }
  if (manifest.tracer && manifest.tracer->adapter != revision->adapter_name) {
    throw UsageError(golden_dir.string() + " holds goldens of adapter '" +
                     manifest.tracer->adapter + "', not '" + revision->adapter_name +
                     "' (use --golden-dir)");
  }
  // Check every scene first, so a bad id or a missing image blesses nothing.
  std::vector<std::pair<const SceneResult*, std::filesystem::path>> chosen;
  for (const std::string& id : ids) {
    const SceneResult* scene = find_scene(document, id);
    if (scene == nullptr) throw UsageError("scene '" + id + "' is not in " + results.string());
    const RunRecord* run = scene->runs.first_run(args.role);
    if (run == nullptr) {
      throw UsageError(results.string() + ": no successful " + args.role + " run of '" + id +
                       "', so no image to bless");
    }
    if (!std::filesystem::is_regular_file(run->image)) {
      throw UsageError(results.string() + ": the " + args.role + " image of '" + id + "', " +
                       run->image.string() + ", is gone (was the run directory removed?)");
    }
    checked_component(id, results.string() + ": scenes[].entry.id");
    checked_image_extension(run->image, results.string() + ": the " + args.role + " image of '" +
                                            id + "'");
    chosen.emplace_back(scene, run->image);
  }

  manifest.suite = document.suite;
  manifest.baseline_version = document.baseline.version;
  manifest.baseline_source_sha256 = document.baseline.source_sha256;
  manifest.tracer = GoldenProvenance{revision->adapter_name, revision->adapter_hash,
                                     revision->worktree.revision, revision->worktree.sha,
                                     revision->worktree.dirty, results.string(),
                                     document.started_at};
  std::filesystem::create_directories(golden_dir);
  for (const auto& [scene, image] : chosen) {
    const SuiteScene& e = scene->entry;
    OIIO_NAMESPACE::ImageBuf decoded(image.string());
    if (!decoded.init_spec(image.string(), 0, 0)) {
      throw UsageError(image.string() + ": cannot read image: " + decoded.geterror());
    }
    const std::string file = e.id + image.extension().string();
    std::filesystem::copy_file(image, golden_dir / file,
                               std::filesystem::copy_options::overwrite_existing);
    // The hash is provenance only: goldens are compared by decoded pixels, never by bytes.
    manifest.upsert({e.id, e.scene, e.size, decoded.spec().width, decoded.spec().height,
                     document.baseline.sampling, "", file, sha256_file_hex(golden_dir / file)});
    save_golden_manifest(manifest, golden_dir);
    fmt::print("blessed   {:<12} {} (from {})\n", e.id, (golden_dir / file).string(),
               image.string());
  }
  return 0;
}

void add_common_options(CLI::App* cmd, GoldenArgs& args) {
  cmd->add_option("--suite", args.suite, "Suite name or file")->capture_default_str();
  cmd->add_option("--golden-dir", args.golden_dir,
                  "Golden directory (default: golden/raygate-baseline/, the baseline's)");
  cmd->add_option("--work-dir", args.work_dir, "Where scenes, renders and evidence go")
      ->capture_default_str();
  cmd->add_option("--baseline", args.baseline, "raygate-baseline to use (default: beside raygate)");
}

}  // namespace

void add_golden_command(CLI::App& app, int& exit_code) {
  CLI::App* golden = app.add_subcommand("golden", "Verify or bless the baseline's golden images");
  golden->require_subcommand(1);

  auto verify_args = std::make_shared<GoldenArgs>();
  CLI::App* verify = golden->add_subcommand("verify", "Re-render and demand identical pixels");
  add_common_options(verify, *verify_args);
  verify->add_option("scenes", verify_args->scenes, "Suite scene ids (default: all)");
  verify->callback([verify_args, &exit_code] { exit_code = run_verify(*verify_args); });

  auto bless_args = std::make_shared<GoldenArgs>();
  CLI::App* bless = golden->add_subcommand("bless", "Re-render and overwrite goldens (on request only)");
  add_common_options(bless, *bless_args);
  bless->add_option("scenes", bless_args->scenes, "Suite scene ids (default: all)");
  bless->add_option("--from-run", bless_args->from_run,
                    "Bless a tracer's images from this results document instead of rendering "
                    "the baseline (default golden dir: golden/<adapter>/)");
  bless->add_option("--role", bless_args->role, "With --from-run: whose images (tracer, head, base)")
      ->capture_default_str();
  bless->callback([bless_args, &exit_code] {
    exit_code = bless_args->from_run.empty() ? run_bless(*bless_args)
                                             : run_bless_from_run(*bless_args);
  });
}

}  // namespace raygate::cli
