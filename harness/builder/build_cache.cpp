#include "builder/build_cache.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/fs.h"
#include "core/path_component.h"
#include "core/sha256.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

constexpr std::size_t kFailedBuildsKept = 3;

// Failed folders of this key: "<key>.failed-N" with N a number.
std::vector<std::pair<int, fs::path>> failed_builds(const BuildCacheEntry& entry) {
  const std::string prefix = entry.key + ".failed-";
  std::vector<std::pair<int, fs::path>> found;
  std::error_code ec;
  for (const auto& item : fs::directory_iterator(entry.dir.parent_path(), ec)) {
    const std::string name = item.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    const bool number =
        !digits.empty() && digits.size() <= 9 &&
        std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!number) continue;  // not one of ours
    found.emplace_back(std::stoi(digits), item.path());
  }
  std::sort(found.begin(), found.end());
  return found;
}

void make_directories(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InfraError("cannot create " + dir.string() + ": " + ec.message());
}

// The build's files must reach the disk before build.json does: after a power cut, a record
// saying success must not point at binaries whose data was never written.
void sync_filesystem_of(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::syncfs(fd);
  ::close(fd);
}

bool matches(const BuildRecord& record, const BuildCacheEntry& entry,
             const BuildKeyInputs& inputs) {
  return record.success && !record.dirty && record.key == entry.key && record.sha == inputs.sha &&
         record.adapter_hash == inputs.adapter_hash && record.compiler == inputs.compiler;
}

// One labelled line per value, each value's bytes hashed, so no two inputs give the same text.
void add_line(std::string& text, const std::string& label, const std::string& value) {
  text += label + " " + sha256_hex(value) + "\n";
}

std::string joined_argv(const std::vector<std::string>& argv) {
  std::string text;
  for (const std::string& arg : argv) text += sha256_hex(arg) + ",";
  return text;
}

}  // namespace

std::map<std::string, std::string> build_environment() {
  static constexpr const char* kNames[] = {"CC",
                                           "CXX",
                                           "CFLAGS",
                                           "CXXFLAGS",
                                           "CPPFLAGS",
                                           "LDFLAGS",
                                           "LIBS",
                                           "CMAKE_GENERATOR",
                                           "CMAKE_BUILD_TYPE",
                                           "CMAKE_PREFIX_PATH",
                                           "CMAKE_TOOLCHAIN_FILE",
                                           "CMAKE_ARGS",
                                           "PKG_CONFIG_PATH",
                                           "CARGO_BUILD_TARGET",
                                           "RUSTFLAGS",
                                           "GOFLAGS",
                                           "CUDAFLAGS",
                                           "FC",
                                           "FFLAGS"};
  std::map<std::string, std::string> found;
  for (const char* name : kNames) {
    if (const char* value = std::getenv(name)) found[name] = value;
  }
  return found;
}

std::string build_inputs_hash(const Adapter& adapter,
                              const std::map<std::string, std::string>& environment) {
  std::string text = "raygate build inputs 1\n";
  for (const std::vector<std::string>& step : adapter.build)
    add_line(text, "step", joined_argv(step));
  add_line(text, "source_dir", adapter.source_dir);
  add_line(text, "requires", joined_argv(adapter.packages));
  text += adapter.submodules ? "submodules\n" : "no-submodules\n";
  for (const auto& [name, value] : environment) add_line(text, "env " + name, value);
  return sha256_hex(text);
}

std::string measurement_hash(const Adapter& adapter, const std::string& build_hash) {
  std::string text = "raygate measurement 1\nbuild " + build_hash + "\n";
  add_line(text, "run", joined_argv(adapter.run));
  add_line(text, "stdin", adapter.stdin_template.value_or("<none>"));
  add_line(text, "cwd", adapter.cwd);
  for (const auto& [name, value] : adapter.env) add_line(text, "env " + name, value);
  text += fmt::format("threads {} pin {} format {}\n", adapter.threads, adapter.pin_cpus,
                      to_string(adapter.scene_format));
  const Timing& t = adapter.timing;
  text += fmt::format("timing {} {} {} {}\n", to_string(t.source),
                      t.metric_by_threads ? "auto" : to_string(t.metric), to_string(t.unit),
                      sha256_hex(t.regex));
  return sha256_hex(text).substr(0, 16);
}

std::string build_key(const BuildKeyInputs& inputs) {
  // Every input on its own labelled line, so no two different inputs hash the same text.
  std::string text = "raygate build key 2\n";  // 2: the adapter's build inputs, not all of it
  text += "sha " + inputs.sha + "\n";
  text += inputs.dirty ? "dirty\n" : "clean\n";
  text += "adapter " + inputs.adapter_name + " " + inputs.adapter_hash + "\n";
  text += "compiler " + sha256_hex(inputs.compiler) + "\n";
  text += "extra " + sha256_hex(inputs.extra) + "\n";
  std::string key = inputs.adapter_name + "-" + inputs.sha.substr(0, 12);
  if (inputs.dirty) key += "-dirty";
  return key + "-" + sha256_hex(text).substr(0, 16);
}

BuildCacheEntry cache_entry(const fs::path& cache_dir, const std::string& key) {
  BuildCacheEntry entry;
  entry.key = key;
  entry.dir = join_component(cache_dir / "builds", key, "build key");
  entry.build_dir = entry.dir / "build";
  entry.logs_dir = entry.dir / "logs";
  entry.record = entry.dir / "build.json";
  entry.lock = cache_dir / "builds" / (key + ".lock");
  return entry;
}

std::optional<BuildRecord> read_cached_build(const BuildCacheEntry& entry,
                                             const BuildKeyInputs& inputs) {
  std::ifstream in(entry.record);
  if (!in) return std::nullopt;
  try {
    BuildRecord record = build_record_from_json(nlohmann::json::parse(in));
    // A cache moved to another path is rebuilt: build trees hold absolute paths (CMake's do).
    if (!matches(record, entry, inputs) || record.build_dir != entry.build_dir ||
        !fs::is_directory(record.build_dir)) {
      return std::nullopt;
    }
    record.cached = true;
    return record;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // torn or foreign: rebuilt, which also replaces it
  }
}

void prepare_fresh_entry(const BuildCacheEntry& entry) {
  std::error_code ec;
  fs::remove_all(entry.dir, ec);
  if (ec) {
    throw InfraError("cannot remove the leftover build " + entry.dir.string() + ": " +
                     ec.message() + "; remove it by hand");
  }
  make_directories(entry.build_dir);
  make_directories(entry.logs_dir);
}

void publish_build(const BuildCacheEntry& entry, const BuildRecord& record) {
  sync_filesystem_of(entry.dir);
  const nlohmann::json json = build_record_to_json(record);
  write_file_atomically(entry.record,
                        json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

fs::path set_aside_failed_build(const BuildCacheEntry& entry) {
  const auto older = failed_builds(entry);
  const int next = older.empty() ? 1 : older.back().first + 1;
  const fs::path target = entry.dir.parent_path() / (entry.key + ".failed-" + std::to_string(next));
  if (std::rename(entry.dir.c_str(), target.c_str()) != 0) return entry.dir;
  // Keep the one just moved and the newest kFailedBuildsKept - 1 before it.
  const std::size_t keep_older = kFailedBuildsKept - 1;
  const std::size_t drop = older.size() > keep_older ? older.size() - keep_older : 0;
  for (std::size_t i = 0; i < drop; ++i) {
    std::error_code ignored;  // an old failure that cannot be deleted only wastes space
    fs::remove_all(older[i].second, ignored);
  }
  return target;
}

}  // namespace raygate
