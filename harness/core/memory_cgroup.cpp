#include "core/memory_cgroup.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "core/enum_words.h"

namespace raygate {
namespace {

constexpr EnumWords<PeakMethod, 4> kPeakMethodWords{{
    {PeakMethod::raygate_process, "raygate-process"},
    {PeakMethod::largest_process, "largest-process"},
    {PeakMethod::cgroup_v1, "cgroup-v1"},
    {PeakMethod::cgroup_v2, "cgroup-v2"},
}};

// Our cgroups are named "raygate-meter-<raygate's pid>-<n>", so a stale one's owner is known.
constexpr std::string_view kPrefix = "raygate-meter-";

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

bool has_token(const std::string& list, char separator, std::string_view token) {
  for (const std::string& part : split(list, separator)) {
    if (part == token) return true;
  }
  return false;
}

// cgroup.subtree_control: "cpu io memory\n".
bool has_word(const std::string& text, std::string_view word) {
  std::istringstream in(text);
  std::string each;
  while (in >> each) {
    if (each == word) return true;
  }
  return false;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A cgroup hierarchy's mount: where it is, and which cgroup path its root is.
struct Hierarchy {
  std::filesystem::path mount_point;
  std::string root;
};

// From /proc/self/mountinfo: the cgroup2 mount (v2), or the cgroup mount with the memory
// controller among its options (v1).
std::optional<Hierarchy> find_hierarchy(bool v2) {
  std::ifstream in("/proc/self/mountinfo");
  std::string line;
  while (std::getline(in, line)) {
    const auto dash = line.find(" - ");
    if (dash == std::string::npos) continue;
    const std::vector<std::string> left = split(line.substr(0, dash), ' ');
    const std::vector<std::string> right = split(line.substr(dash + 3), ' ');
    if (left.size() < 5 || right.size() < 3) continue;
    const bool wanted =
        v2 ? right[0] == "cgroup2" : right[0] == "cgroup" && has_token(right[2], ',', "memory");
    if (wanted) return Hierarchy{left[4], left[3]};
  }
  return std::nullopt;
}

// This process's cgroup in that hierarchy, from /proc/self/cgroup ("0::/a/b" for v2,
// "4:memory:/a/b" for v1), as a directory under the mount point.
std::optional<std::filesystem::path> own_cgroup(const Hierarchy& h, bool v2) {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find(':');
    const auto second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const bool wanted = v2 ? line.substr(0, first) == "0" && controllers.empty()
                           : has_token(controllers, ',', "memory");
    if (!wanted) continue;
    std::string path = line.substr(second + 1);
    if (h.root != "/") {
      if (path.rfind(h.root, 0) != 0) return std::nullopt;  // outside the mounted subtree
      path = path.substr(h.root.size());
    }
    return h.mount_point / std::filesystem::path(path).relative_path();
  }
  return std::nullopt;
}

// Kills every process in the cgroup (they are ours: raygate-meter's tree, or a dead raygate's).
void kill_members(const std::filesystem::path& directory) {
  std::istringstream pids(read_text(directory / "cgroup.procs"));
  pid_t pid = 0;
  while (pids >> pid) {
    if (pid > 0) ::kill(pid, SIGKILL);
  }
}

// Kills what is left and removes the cgroup; a killed process leaves it within milliseconds.
bool remove_cgroup(const std::filesystem::path& directory) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    if (::rmdir(directory.c_str()) == 0 || errno == ENOENT) return true;
    if (errno != EBUSY) return false;
    kill_members(directory);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

// Cgroups that a raygate no longer running left behind (it was SIGKILLed mid-run).
void remove_stale(const std::filesystem::path& parent) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(kPrefix, 0) != 0) continue;
    const pid_t owner = static_cast<pid_t>(std::atol(name.c_str() + kPrefix.size()));
    if (owner > 0 && ::kill(owner, 0) != 0 && errno == ESRCH) remove_cgroup(entry.path());
  }
}

std::optional<std::filesystem::path> make_directory(const std::filesystem::path& parent,
                                                    std::string& why_not) {
  remove_stale(parent);
  for (int n = 0; n < 1000; ++n) {
    const std::filesystem::path directory =
        parent / (std::string(kPrefix) + std::to_string(::getpid()) + "-" + std::to_string(n));
    if (::mkdir(directory.c_str(), 0755) == 0) return directory;
    if (errno != EEXIST) {
      why_not = "cannot create " + directory.string() + ": " + std::strerror(errno);
      return std::nullopt;
    }
  }
  why_not = "no free cgroup name under " + parent.string();
  return std::nullopt;
}

// v2: a sibling of this process's cgroup (a cgroup with processes cannot enable controllers for
// children, except the root), which needs the memory controller enabled in the parent.
std::optional<std::filesystem::path> v2_parent(std::string& why_not) {
  const auto h = find_hierarchy(true);
  const auto own = h ? own_cgroup(*h, true) : std::nullopt;
  if (!own) {
    why_not = "no cgroup v2 hierarchy";
    return std::nullopt;
  }
  const std::filesystem::path parent = *own == h->mount_point ? *own : own->parent_path();
  if (!has_word(read_text(parent / "cgroup.subtree_control"), "memory")) {
    why_not = "cgroup v2 has no memory controller at " + parent.string();
    return std::nullopt;
  }
  return parent;
}

std::optional<std::filesystem::path> v1_parent(std::string& why_not) {
  const auto h = find_hierarchy(false);
  const auto own = h ? own_cgroup(*h, false) : std::nullopt;
  if (!own) {
    why_not += "; no cgroup v1 memory hierarchy";
    return std::nullopt;
  }
  return *own;
}

std::optional<long> read_bytes_as_kib(const std::filesystem::path& file) {
  std::ifstream in(file);
  unsigned long long bytes = 0;
  if (!(in >> bytes)) return std::nullopt;
  return static_cast<long>(bytes / 1024);
}

const char* peak_file(PeakMethod method) {
  return method == PeakMethod::cgroup_v2 ? "memory.peak" : "memory.max_usage_in_bytes";
}

}  // namespace

std::string_view to_string(PeakMethod method) { return word_of(kPeakMethodWords, method); }

std::optional<PeakMethod> parse_peak_method(std::string_view word) {
  return value_of(kPeakMethodWords, word);
}

std::string describe_peak_method(PeakMethod method) {
  switch (method) {
    case PeakMethod::cgroup_v2: return "whole process tree at once (cgroup v2 memory.peak)";
    case PeakMethod::cgroup_v1:
      return "whole process tree at once (cgroup v1 memory.max_usage_in_bytes)";
    case PeakMethod::largest_process:
      return "largest single process (no memory cgroup could be made here)";
    case PeakMethod::raygate_process: break;
  }
  return "own process as raygate saw it (not metered)";
}

std::optional<MemoryCgroup> MemoryCgroup::create(std::string* why_not) {
  std::string reason;
  for (const PeakMethod method : {PeakMethod::cgroup_v2, PeakMethod::cgroup_v1}) {
    const auto parent = method == PeakMethod::cgroup_v2 ? v2_parent(reason) : v1_parent(reason);
    if (!parent) continue;
    std::string made_why;
    const auto directory = make_directory(*parent, made_why);
    if (!directory) {
      reason += (reason.empty() ? "" : "; ") + made_why;
      continue;
    }
    MemoryCgroup cgroup(*directory, method);
    if (cgroup.peak_kib()) return cgroup;
    reason += "; no " + std::string(peak_file(method)) + " in " + directory->string();
  }  // a cgroup without its counter was removed by its destructor
  if (why_not != nullptr) *why_not = reason;
  return std::nullopt;
}

MemoryCgroup::MemoryCgroup(MemoryCgroup&& other) noexcept
    : directory_(std::exchange(other.directory_, {})), method_(other.method_) {}

MemoryCgroup& MemoryCgroup::operator=(MemoryCgroup&& other) noexcept {
  if (this != &other) {
    if (!directory_.empty()) remove_cgroup(directory_);
    directory_ = std::exchange(other.directory_, {});
    method_ = other.method_;
  }
  return *this;
}

MemoryCgroup::~MemoryCgroup() {
  if (!directory_.empty()) remove_cgroup(directory_);
}

std::optional<long> MemoryCgroup::peak_kib() const {
  if (directory_.empty()) return std::nullopt;
  return read_bytes_as_kib(directory_ / peak_file(method_));
}

}  // namespace raygate
