#include "explain/callgrind_profile.h"

#include <fmt/core.h>

#include <charconv>
#include <map>
#include <vector>

#include "core/error.h"
#include "core/fs.h"
#include "explain/profile_fields.h"

namespace raygate {
namespace {

// The kinds of names, each with its own compression ids.
enum class NameKind { file, function, object };

class CallgrindReader {
 public:
  explicit CallgrindReader(const std::string& origin) : origin_(origin) {}

  void line(std::string_view text, int number) {
    number_ = number;
    if (text.empty() || text[0] == '#') return;
    if (is_cost_line(text)) return cost_line(text);
    const std::size_t eq = text.find('=');
    const std::size_t colon = text.find(':');
    if (colon != std::string_view::npos && (eq == std::string_view::npos || colon < eq)) {
      return header(text.substr(0, colon), text.substr(colon + 1));
    }
    if (eq != std::string_view::npos) spec(text.substr(0, eq), text.substr(eq + 1));
  }

  FunctionProfile finish() {
    if (events_.empty()) fail("no 'events:' line (not callgrind output?)");
    for (auto& [name, cost] : profile_) {
      cost.inclusive += cost.self;
      cost.inclusive_known = true;
    }
    return std::move(profile_);
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw InfraError(fmt::format("{}:{}: {}", origin_, number_, why));
  }

  // A position (line, "+N", "-N", "*", or 0x... with --dump-instr) then counts.
  static bool is_cost_line(std::string_view text) {
    const char c = text[0];
    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '*';
  }

  void header(std::string_view key, std::string_view value) {
    if (key == "events") {
      events_.clear();
      for (const std::string_view e : profile_fields(value)) events_.emplace_back(e);
    } else if (key == "positions") {
      positions_ = profile_fields(value).size();
    }
  }

  void spec(std::string_view key, std::string_view value) {
    if (key == "fn") {
      function_ = name(NameKind::function, value);
      FunctionCost& cost = profile_[function_];
      if (cost.name.empty()) {
        cost.name = function_;
        cost.file = file_;
      }
    } else if (key == "fl" || key == "fi" || key == "fe") {
      file_ = name(NameKind::file, value);
    } else if (key == "cfn") {
      callee_ = name(NameKind::function, value);
    } else if (key == "cfl" || key == "cfi") {
      name(NameKind::file, value);  // defines its id; the callee's file is not needed
    } else if (key == "ob" || key == "cob") {
      name(NameKind::object, value);
    } else if (key == "calls") {
      call_pending_ = true;  // the next cost line is the call's inclusive cost
    }
    // jump=, jcnd= (--collect-jumps) and anything newer: not costs, ignored.
  }

  // "(id) name" defines id; "(id)" refers to it; a plain name is itself.
  std::string name(NameKind kind, std::string_view value) {
    if (value.empty() || value[0] != '(') return demangled_name(kind, value);
    const std::size_t close = value.find(')');
    if (close == std::string_view::npos) fail(fmt::format("'{}': no ')' after the id", value));
    const std::string id(value.substr(1, close - 1));
    std::map<std::string, std::string>& ids = ids_[static_cast<int>(kind)];
    std::string_view rest = value.substr(close + 1);
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    if (!rest.empty()) return ids[id] = demangled_name(kind, rest);
    const auto found = ids.find(id);
    if (found == ids.end()) fail(fmt::format("name id ({}) used before it is defined", id));
    return found->second;
  }

  static std::string demangled_name(NameKind kind, std::string_view value) {
    return kind == NameKind::function ? demangled(value) : std::string(value);
  }

  void cost_line(std::string_view text) {
    if (function_.empty()) fail("a cost line before any 'fn=' line");
    const std::vector<std::string_view> fields = profile_fields(text);
    if (fields.size() < positions_) fail("a cost line without its position");
    if (fields.size() - positions_ > events_.size()) {
      fail(fmt::format("{} counts for the {} events named", fields.size() - positions_,
                       events_.size()));
    }
    SimulatedCounters counts;
    for (std::size_t i = positions_; i < fields.size(); ++i) {
      std::uint64_t value = 0;
      const std::string_view f = fields[i];
      const auto [end, error] = std::from_chars(f.data(), f.data() + f.size(), value);
      if (error != std::errc() || end != f.data() + f.size()) {
        fail(fmt::format("'{}' is not a count", f));
      }
      if (std::uint64_t* counter = counter_named(counts, events_[i - positions_]))
        *counter += value;
    }
    FunctionCost& cost = profile_[function_];
    if (!call_pending_) {
      cost.self += counts;
    } else if (callee_ != function_) {  // a direct recursion's cost is in self already
      cost.inclusive += counts;
    }
    call_pending_ = false;
  }

  const std::string& origin_;
  std::vector<std::string> events_;
  std::size_t positions_ = 1;  // "positions: line" unless the file says otherwise
  std::map<std::string, std::string> ids_[3];
  std::string file_;
  std::string function_;
  std::string callee_;
  bool call_pending_ = false;
  int number_ = 0;
  FunctionProfile profile_;
};

}  // namespace

FunctionProfile parse_callgrind_profile(std::string_view text, const std::string& origin) {
  return read_profile_lines<CallgrindReader>(text, origin);
}

FunctionProfile read_callgrind_profiles(const std::filesystem::path& dir) {
  return sum_profile_files(dir, "callgrind.out.", "callgrind", &parse_callgrind_profile);
}

ProcessSpec under_callgrind(ProcessSpec spec, const Cachegrind& valgrind,
                            const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  std::vector<std::string> argv = {
      valgrind.command, "--tool=callgrind", "--trace-children=yes",
      // One entry per recursive function (not "f'2" for its deeper calls); the reader leaves
      // its recursive calls out of its inclusive cost.
      "--separate-recs=1",
      // %p: one file per process (a wrapper's children too).
      "--callgrind-out-file=" + (out_dir / "callgrind.out.%p").string()};
  argv.insert(argv.end(), spec.argv.begin(), spec.argv.end());
  spec.argv = std::move(argv);
  return spec;
}

}  // namespace raygate
