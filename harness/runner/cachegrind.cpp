#include "runner/cachegrind.h"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <map>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/fs.h"
#include "measure/counted_spread.h"

namespace raygate {

namespace {

// A fixed, typical geometry (32 KiB 8-way L1s, 8 MiB 16-way last level, 64-byte lines) instead
// of cachegrind's default, the host's own caches: those differ between runners (this VM reports
// a 512 MiB 2-way "LL"), and the counts would with them.
const std::vector<std::string> kCacheGeometry = {"--I1=32768,8,64", "--D1=32768,8,64",
                                                 "--LL=8388608,16,64"};

std::vector<std::string> words(std::string_view text) {
  std::vector<std::string> out;
  std::istringstream in{std::string(text)};
  for (std::string word; in >> word;) out.push_back(word);
  return out;
}

std::uint64_t parse_count(const std::string& word, const std::string& where) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) {
    throw InfraError(fmt::format("{}: summary count '{}' is not a whole number", where, word));
  }
  return value;
}

std::uint64_t event(const std::map<std::string, std::uint64_t>& totals, const char* name,
                    const std::string& where) {
  const auto found = totals.find(name);
  if (found == totals.end()) {
    throw InfraError(
        fmt::format("{}: no '{}' event (was cachegrind run with --cache-sim=yes?)", where, name));
  }
  return found->second;
}

}  // namespace

Cachegrind find_cachegrind() {
  Cachegrind found;
  TempDir temp("raygate-valgrind");
  ProcessSpec spec;
  spec.argv = {found.command, "--version"};
  spec.stdout_path = temp.path() / "version.txt";
  spec.timeout = std::chrono::seconds(30);
  const ProcessResult result = run_process(spec);
  if (!result.succeeded()) {
    throw InfraError(fmt::format(
        "--timing sim runs every tracer and baseline process under Valgrind's cachegrind, but "
        "'valgrind --version' {}{}: install Debian's valgrind package (ci/install-deps does)",
        result.describe(), result.spawn_error.empty() ? "" : " (" + result.spawn_error + ")"));
  }
  const std::string text = read_file(spec.stdout_path);
  found.version = text.substr(0, text.find('\n'));
  return found;
}

ProcessSpec under_cachegrind(ProcessSpec spec, const Cachegrind& cachegrind,
                             const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  std::vector<std::string> argv = {cachegrind.command, "--tool=cachegrind", "--cache-sim=yes",
                                   "--branch-sim=no", "--trace-children=yes"};
  argv.insert(argv.end(), kCacheGeometry.begin(), kCacheGeometry.end());
  // %p: one file per process; an exec keeps the pid, so a wrapper that execs is counted once.
  argv.push_back("--cachegrind-out-file=" + (out_dir / "cg.%p").string());
  argv.insert(argv.end(), spec.argv.begin(), spec.argv.end());
  spec.argv = std::move(argv);
  return spec;
}

SimulatedCounters parse_cachegrind_output(std::string_view text, const std::string& origin) {
  std::vector<std::string> names;
  std::vector<std::string> counts;
  int events_line = 0;
  int summary_line = 0;
  int number = 0;
  std::istringstream in{std::string(text)};
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.starts_with("events:")) {
      names = words(std::string_view(line).substr(7));
      events_line = number;
    } else if (line.starts_with("summary:")) {
      counts = words(std::string_view(line).substr(8));
      summary_line = number;
    }
  }
  if (events_line == 0) throw InfraError(origin + ": no 'events:' line (not cachegrind output?)");
  if (summary_line == 0) {
    throw InfraError(origin + ": no 'summary:' line (the process was killed before it ended?)");
  }
  const std::string where = fmt::format("{}:{}", origin, summary_line);
  if (counts.size() != names.size()) {
    throw InfraError(fmt::format("{}: {} counts for the {} events named on line {}", where,
                                 counts.size(), names.size(), events_line));
  }
  std::map<std::string, std::uint64_t> totals;
  for (std::size_t i = 0; i < names.size(); ++i) totals[names[i]] = parse_count(counts[i], where);
  SimulatedCounters out;
  out.ir = event(totals, "Ir", where);
  out.i1mr = event(totals, "I1mr", where);
  out.ilmr = event(totals, "ILmr", where);
  out.dr = event(totals, "Dr", where);
  out.d1mr = event(totals, "D1mr", where);
  out.dlmr = event(totals, "DLmr", where);
  out.dw = event(totals, "Dw", where);
  out.d1mw = event(totals, "D1mw", where);
  out.dlmw = event(totals, "DLmw", where);
  out.processes = 1;
  return out;
}

SimulatedCounters read_cachegrind_outputs(const std::filesystem::path& out_dir) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(out_dir, error)) {
    if (entry.path().filename().string().starts_with("cg.")) files.push_back(entry.path());
  }
  if (files.empty()) {
    throw InfraError("cachegrind wrote no output file in " + out_dir.string() +
                     (error ? " (" + error.message() + ")" : ""));
  }
  std::sort(files.begin(), files.end());
  SimulatedCounters total;
  for (const auto& file : files) total += parse_cachegrind_output(read_file(file), file.string());
  return total;
}

void record_simulated_cost(RunRecord& run, const std::filesystem::path& out_dir) {
  try {
    run.simulated = read_cachegrind_outputs(out_dir);
    run.seconds = estimated_cycles(*run.simulated);
  } catch (const InfraError& e) {
    run.ok = false;
    run.failure = e.what();
  }
}

std::string determinism_note(const SceneRuns& runs) {
  std::map<std::string, std::vector<double>> costs;  // by role
  for (const Round& round : runs.rounds) {
    for (const auto& [role, run] : round.runs) {
      if (run.simulated) costs[role].push_back(run.seconds);
    }
  }
  if (costs.empty()) return {};
  std::string spreads;
  double widest = 0.0;
  for (const auto& [role, values] : costs) {
    if (const double spread = relative_spread(values); spread > 0.0) {
      spreads += fmt::format("{}{} {:.4g}%", spreads.empty() ? "" : ", ", role, 100 * spread);
      widest = std::max(widest, spread);
    }
  }
  if (spreads.empty()) return "simulated cycles, counts repeat exactly";
  if (counts_agree(widest)) {
    return fmt::format("simulated cycles repeat within {:g}% (spread: {}): counted",
                       100 * kCountedSpreadTolerance, spreads);
  }
  return fmt::format(
      "simulated cycles differ between runs by more than {:g}% (spread: {}): timed "
      "statistics",
      100 * kCountedSpreadTolerance, spreads);
}

std::filesystem::path cachegrind_dir(const std::filesystem::path& run_dir) {
  return run_dir / "cachegrind";
}

}  // namespace raygate
