#include "explain/function_profile.h"

#include <cxxabi.h>
#include <fmt/core.h>

#include <charconv>
#include <cstdlib>
#include <memory>
#include <vector>

#include "core/error.h"
#include "core/fs.h"
#include "explain/profile_fields.h"

namespace raygate {
namespace {

// One file's parse: the events' order, the current file and function, the costs so far.
class ProfileReader {
 public:
  explicit ProfileReader(const std::string& origin) : origin_(origin) {}

  void line(std::string_view text, int number) {
    number_ = number;
    if (text.starts_with("events:")) {
      events_.clear();
      for (const std::string_view e : profile_fields(text.substr(7))) events_.emplace_back(e);
    } else if (text.starts_with("fl=") || text.starts_with("fi=") || text.starts_with("fe=")) {
      file_ = std::string(text.substr(3));
    } else if (text.starts_with("fn=")) {
      function_ = demangled(text.substr(3));
    } else if (!text.empty() && text[0] >= '0' && text[0] <= '9') {
      add_costs(text);
    }
  }

  FunctionProfile finish() {
    if (events_.empty()) throw InfraError(origin_ + ": no 'events:' line (not cachegrind output?)");
    return std::move(profile_);
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw InfraError(fmt::format("{}:{}: {}", origin_, number_, why));
  }

  void add_costs(std::string_view text) {
    if (function_.empty()) fail("a cost line before any 'fn=' line");
    const std::vector<std::string_view> fields = profile_fields(text);
    if (fields.size() - 1 > events_.size()) {
      fail(fmt::format("{} counts for the {} events named", fields.size() - 1, events_.size()));
    }
    FunctionCost& cost = profile_[function_];
    if (cost.name.empty()) {
      cost.name = function_;
      cost.file = file_;
    }
    for (std::size_t i = 1; i < fields.size(); ++i) {
      std::uint64_t value = 0;
      const std::string_view f = fields[i];
      const auto [end, error] = std::from_chars(f.data(), f.data() + f.size(), value);
      if (error != std::errc() || end != f.data() + f.size()) {
        fail(fmt::format("'{}' is not a count", f));
      }
      if (std::uint64_t* counter = counter_named(cost.self, events_[i - 1])) *counter += value;
    }
  }

  const std::string& origin_;
  std::vector<std::string> events_;
  std::string file_;
  std::string function_;
  int number_ = 0;
  FunctionProfile profile_;
};

void add_into(FunctionProfile& sum, const FunctionProfile& part) {
  for (const auto& [name, cost] : part) {
    FunctionCost& into = sum[name];
    if (into.name.empty()) {
      into.name = cost.name;
      into.file = cost.file;
    }
    into.self += cost.self;
    into.inclusive += cost.inclusive;
    into.inclusive_known = into.inclusive_known || cost.inclusive_known;
  }
}

}  // namespace

std::string demangled(std::string_view symbol) {
  const std::string name(symbol);
  if (!name.starts_with("_Z")) return name;
  int status = 0;
  const std::unique_ptr<char, decltype(&std::free)> text(
      abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status), &std::free);
  return status == 0 && text ? std::string(text.get()) : name;
}

FunctionProfile parse_function_profile(std::string_view text, const std::string& origin) {
  return read_profile_lines<ProfileReader>(text, origin);
}

FunctionProfile sum_profile_files(const std::filesystem::path& dir, std::string_view prefix,
                                  std::string_view tool, ProfileParser parse) {
  FunctionProfile sum;
  bool any = false;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (!entry.path().filename().string().starts_with(prefix)) continue;
    add_into(sum, parse(read_file(entry.path()), entry.path().string()));
    any = true;
  }
  if (!any) throw InfraError(fmt::format("no {} output in {}", tool, dir.string()));
  return sum;
}

FunctionProfile read_function_profiles(const std::filesystem::path& dir) {
  return sum_profile_files(dir, "cg.", "cachegrind", &parse_function_profile);
}

}  // namespace raygate
