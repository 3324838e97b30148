// `raygate history`: the normalized ratio and image error of each scene over commits, from the
// results store, one table per repository and adapter with each series' trend (results/series.h),
// and a note when the machine drifted rather than the code. `--format json` for machines, `--html DIR`
// for a page of plots. Exit 0, 2 for a bad store.
#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/store_options.h"
#include "cli/subcommand.h"
#include "core/fs.h"
#include "history/history_view.h"
#include "pipeline/store_commands.h"

namespace raygate::cli {
namespace {

struct HistoryArgs {
  std::string store = kDefaultStorePath;
  HistoryQuery query = [] {
    HistoryQuery q;
    q.last_commits = 20;
    return q;
  }();
  std::string format;  // text, json
  std::string html_dir;
};

int history_command(const HistoryArgs& args) {
  const std::filesystem::path page = history_page(args.html_dir);  // checked before reading
  const HistoryView view = store_history_view(args.store, args.query);
  if (!page.empty()) {
    write_file_atomically(page, history_html(view));
    fmt::print(stderr, "history page: {}\n", page.string());
  }
  print_result(
      args.format, [&] { return history_json(view); }, [&] { return history_table(view); });
  return 0;
}

}  // namespace

void add_history_command(CLI::App& command, int& exit_code) {
  HistoryArgs& args = bind_command<HistoryArgs>(command, history_command, exit_code);
  add_store_option(command, args.store, kDefaultStorePath);
  add_history_filters(command, args.query);
  add_bounded_option(command, "--last", args.query.last_commits, std::size_t{0},
                     std::size_t{1000000}, "the newest N commits of each table (0: all)");
  command.add_option("--series", args.query.series,
                     "only this series (an id from --format json, or its first digits)");
  command.add_flag("--include-dirty", args.query.include_dirty,
                   "also trees measured with local changes (each its own point)");
  add_format_option(command, args.format, {"text", "json"}, true);
  command.add_option("--html", args.html_dir, "also write DIR/history.html with SVG plots")
      ->check(writable_folder());
}

}  // namespace raygate::cli
