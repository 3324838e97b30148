#include "pipeline/golden_commands.h"

#include <fmt/core.h>

#include <optional>

#include "core/format.h"
#include "core/error.h"

namespace raygate {
namespace {

BaselineGoldens open_goldens(const GoldenOptions& options) {
  return open_baseline_goldens(options.suite.empty() ? "ci" : options.suite, options.scenes,
                               options.golden_dir, options.work_dir, options.baseline);
}

// What the options ask that raygate would do wrongly or not at all, refused before any work:
// --work-dir in the golden folder itself (its scenes/, renders/ and evidence/ would sit among
// the goldens), --role, which only --from-run reads, and --suite beside it, which it cannot.
void check_golden_options(const GoldenOptions& options) {
  if (!options.role.empty() && options.from_run.empty()) {
    throw UsageError("--role " + options.role +
                     ": whose images to take from a results document, so it needs --from-run");
  }
  if (!options.suite.empty() && !options.from_run.empty()) {
    throw UsageError("--suite " + options.suite +
                     ": --from-run takes the suite its results document was measured on; leave "
                     "--suite out");
  }
  if (options.golden_dir.empty()) return;
  std::error_code error;
  const auto folder = [&error](const std::string& path) {
    const std::filesystem::path named =
        std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
    return named.has_filename() ? named : named.parent_path();  // "dir/" is "dir"
  };
  if (folder(options.work_dir) == folder(options.golden_dir)) {
    throw UsageError(fmt::format(
        "--work-dir and --golden-dir are the same folder, {}: the scenes, renders and evidence "
        "would sit among the goldens; give --work-dir a folder of its own",
        folder(options.golden_dir).string()));
  }
}

}  // namespace

BlessFromRun from_run_request(const GoldenOptions& options) {
  BlessFromRun request;
  request.results = std::filesystem::absolute(options.from_run);
  const std::optional<Role> role = parse_role(options.role.empty() ? "tracer" : options.role);
  if (!role || *role == Role::baseline) {
    throw UsageError("--role: no such revision role '" + options.role + "' (tracer, base or head)");
  }
  request.role = *role;
  request.scene_ids = options.scenes;
  request.golden_dir = options.golden_dir;
  request.baseline = options.baseline;
  return request;
}

GoldenOutcome baseline_verification_outcome(const GoldenVerification& v, std::size_t scenes) {
  std::string summary =
      fmt::format("{}: {} identical, {} different, {} missing", count_text(scenes, "scene"),
                  v.identical, v.different, v.missing);
  if (v.unverifiable > 0)
    summary += fmt::format(", {} not to be trusted", count_text(v.unverifiable, "golden"));
  if (v.missing > 0) return {summary, ExitCode::usage};  // a scene asked for has no golden
  // A difference found outranks a golden that could not verify (3).
  if (v.different > 0) return {summary, ExitCode::regression};
  return {summary, v.unverifiable > 0 ? ExitCode::infrastructure : ExitCode::pass};
}

GoldenOutcome run_verification_outcome(const GoldenVerification& v) {
  const std::size_t scenes =
      v.identical + v.different + v.inconclusive + v.missing + v.unverifiable;
  std::string summary =
      fmt::format("{}: {} same, {} different, {} too noisy to tell, {} missing",
                  count_text(scenes, "scene"), v.identical, v.different, v.inconclusive, v.missing);
  if (v.unverifiable > 0)
    summary += fmt::format(", {} not to be trusted", count_text(v.unverifiable, "golden"));
  if (v.different > 0) return {summary, ExitCode::regression};
  if (v.unverifiable > 0) return {summary, ExitCode::infrastructure};
  return {summary, v.missing > 0 ? ExitCode::usage : ExitCode::pass};
}

GoldenOutcome verify_goldens(const GoldenOptions& options, ProgressSink& lines) {
  check_golden_options(options);
  // Said once, not as 13 "MISSING ... create it with bless" lines (a sweep): a mistyped folder.
  if (std::error_code absent; !options.golden_dir.empty() &&
                              !std::filesystem::exists(options.golden_dir, absent) && !absent) {
    throw UsageError("--golden-dir " + options.golden_dir +
                     " does not exist: no goldens to verify (bless a set there first: raygate "
                     "golden bless --golden-dir " +
                     options.golden_dir + ")");
  }
  if (!options.from_run.empty()) {
    return run_verification_outcome(verify_goldens_from_run(
        from_run_request(options), std::filesystem::path(options.work_dir) / "evidence", lines));
  }
  const BaselineGoldens goldens = open_goldens(options);
  return baseline_verification_outcome(verify_baseline_goldens(goldens, lines),
                                       goldens.selected.size());
}

void bless_goldens(const GoldenOptions& options, ProgressSink& lines) {
  check_golden_options(options);
  if (options.from_run.empty()) {
    bless_baseline_goldens(open_goldens(options), lines);
  } else {
    bless_goldens_from_run(from_run_request(options), lines);
  }
}

}  // namespace raygate
