// `raygate history`: the normalized ratio and image error of each scene over commits, from the
// results store, one table per repository and adapter with each series' trend (store/series.h),
// and a note when the machine drifted rather than the code. `--format json` for machines, `--html DIR`
// for a page of plots. Exit 0, 2 for a bad store.
#include <fmt/core.h>

#include <memory>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/history_view.h"
#include "cli/store_commands.h"
#include "cli/store_options.h"
#include "core/fs.h"
#include "store/store.h"

namespace raygate::cli {
namespace {

struct HistoryArgs {
  std::string store = kDefaultStorePath;
  std::string branch;
  std::vector<std::string> scenes;
  std::size_t last = 20;
  std::string role = "tracer";
  std::string repository;
  std::string adapter;
  std::string suite;
  std::string series;
  bool include_dirty = false;
  std::string format;  // text, json
  std::string html_dir;
};

HistoryQuery history_query(const HistoryArgs& args) {
  HistoryQuery query;
  query.branch = args.branch;
  query.scenes = args.scenes;
  query.role = args.role;
  query.include_dirty = args.include_dirty;
  query.last_commits = args.last;
  query.repository = args.repository;
  query.adapter = args.adapter;
  query.suite = args.suite;
  query.series = args.series;
  return query;
}

// The machine's own history for the drift rule: every document, any branch, any series (the
// rule compares each series only with itself).
HistoryQuery machine_query(const HistoryQuery& query) {
  HistoryQuery machine = query;
  machine.branch.clear();
  machine.last_commits = 0;
  machine.repository.clear();
  machine.adapter.clear();
  machine.suite.clear();
  machine.series.clear();
  return machine;
}

void write_html(const HistoryView& view, const std::string& dir) {
  const std::filesystem::path page = std::filesystem::path(dir) / "history.html";
  write_file_atomically(page, history_html(view));
  fmt::print(stderr, "history page: {}\n", page.string());
}

int history_command(const HistoryArgs& args) {
  const auto store = open_store(args.store, StoreOpen::must_exist);
  const HistoryQuery query = history_query(args);
  HistoryView view = make_history_view(store->measurements(query), query.last_commits,
                                       store->measurements(machine_query(query)));
  view.store = store->location();
  view.role = args.role;
  view.branch = args.branch;
  if (!args.html_dir.empty()) write_html(view, args.html_dir);
  if (args.format == "json") {
    fmt::print("{}\n", history_json(view).dump(1));
  } else {
    fmt::print("{}", history_table(view));
  }
  return 0;
}

void add_history_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<HistoryArgs>();
  CLI::App* command = app.add_subcommand(
      "history", "normalized ratio and image error per scene over commits, from the store");
  add_store_option(*command, args->store, kDefaultStorePath);
  command->add_option("--branch", args->branch, "only results recorded under this branch");
  command->add_option("--scene", args->scenes, "only these suite scene ids (repeatable)");
  command->add_option("--last", args->last, "the newest N commits of each table (0: all)")
      ->capture_default_str();
  command->add_option("--repository", args->repository,
                      "only the repository whose key contains this text (its root commit sha "
                      "or URL, as the table headings show)");
  command->add_option("--adapter", args->adapter, "only results measured with this adapter");
  command->add_option("--suite", args->suite, "only results of this suite");
  command->add_option("--series", args->series,
                      "only this series (an id from --format json, or its first digits)");
  command
      ->add_option("--role", args->role,
                   "which revision of a document: tracer (run), head or base (compare), any")
      ->check(CLI::IsMember({"tracer", "head", "base", "any"}))
      ->capture_default_str();
  command->add_flag("--include-dirty", args->include_dirty,
                    "also trees measured with local changes (each its own point)");
  add_format_option(*command, args->format, {"text", "json"}, true);
  command->add_option("--html", args->html_dir, "also write DIR/history.html with SVG plots");
  command->callback([args, &exit_code] { exit_code = history_command(*args); });
}

}  // namespace

void add_history_commands(CLI::App& app, int& exit_code) {
  add_history_command(app, exit_code);
  add_import_command(app, exit_code);
  add_export_command(app, exit_code);
}

}  // namespace raygate::cli
