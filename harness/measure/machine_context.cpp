#include "measure/machine_context.h"

#include <linux/perf_event.h>
#include <sched.h>
#include <sys/syscall.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/fs.h"
#include "core/text.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

// Calls visit(key, value) for each "key : value" line, trimmed.
template <typename Visit>
void for_each_field(std::string_view text, Visit visit) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    const auto colon = line.find(':');
    if (colon != std::string_view::npos) {
      visit(trim_blanks(line.substr(0, colon)), trim_blanks(line.substr(colon + 1)));
    }
    start = end + 1;
  }
}

std::optional<long long> parse_integer(std::string_view text) {
  text = trim_blanks(text);
  if (text.empty()) return std::nullopt;
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(copy.c_str(), &end, 10);
  if (errno != 0 || end != copy.c_str() + copy.size()) return std::nullopt;
  return value;
}

fs::path under_root(const fs::path& root, std::string_view absolute) {
  return root / fs::path(absolute).relative_path();
}

bool is_cpu_directory_name(const std::string& name) {
  return name.size() > 3 && name.compare(0, 3, "cpu") == 0 &&
         std::all_of(name.begin() + 3, name.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::vector<std::string> probe_governors(const fs::path& root) {
  std::set<std::string> governors;
  for (const auto& [cpu, governor] : cpu_governors(root)) governors.insert(governor);
  return {governors.begin(), governors.end()};
}

std::optional<bool> probe_turbo(const fs::path& root) {
  // intel_pstate says "no turbo"; acpi-cpufreq and amd-pstate say "boost".
  if (auto text =
          read_pseudo_file(under_root(root, "/sys/devices/system/cpu/intel_pstate/no_turbo"))) {
    if (auto value = parse_integer(*text)) return *value == 0;
  }
  if (auto text = read_pseudo_file(under_root(root, "/sys/devices/system/cpu/cpufreq/boost"))) {
    if (auto value = parse_integer(*text)) return *value != 0;
  }
  return std::nullopt;
}

std::optional<int> probe_allowed_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return std::nullopt;
  return CPU_COUNT(&set);
}

std::string probe_kernel() {
  utsname names{};
  if (uname(&names) != 0) return {};
  return std::string(names.sysname) + " " + names.release + " " + names.version + " " +
         names.machine;
}

std::string probe_hostname() {
  char name[256] = {};
  if (gethostname(name, sizeof(name) - 1) != 0) return {};
  return name;
}

// strerror alone ("No such file or directory") does not tell a user what to do.
std::string describe_perf_errno(int error) {
  const std::string reason = std::strerror(error);
  switch (error) {
    case ENOENT:
    case EOPNOTSUPP:
      return reason + ": no hardware instruction counter (virtual machine or unsupported PMU)";
    case EACCES:
    case EPERM:
      return reason +
             ": not permitted (see /proc/sys/kernel/perf_event_paranoid, or a seccomp "
             "profile of the container)";
    case ENOSYS: return reason + ": kernel without perf_event_open";
    default: return reason;
  }
}

// Opens (and closes at once) a counter of this process's user-space instructions: the same kind
// of counter the runner would attach to a tracer. Returns the reason when the kernel refuses.
std::string probe_perf_instructions() {
  perf_event_attr attributes;
  std::memset(&attributes, 0, sizeof(attributes));
  attributes.type = PERF_TYPE_HARDWARE;
  attributes.size = sizeof(attributes);
  attributes.config = PERF_COUNT_HW_INSTRUCTIONS;
  attributes.disabled = 1;
  attributes.exclude_kernel = 1;  // allowed up to perf_event_paranoid 2
  attributes.exclude_hv = 1;
  const long fd = syscall(SYS_perf_event_open, &attributes, 0 /* self */, -1 /* any CPU */,
                          -1 /* no group */, 0UL);
  if (fd < 0) return describe_perf_errno(errno);
  close(static_cast<int>(fd));
  return {};
}

template <typename T>
nlohmann::json or_null(const std::optional<T>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json or_null(const std::string& value) {
  return value.empty() ? nlohmann::json(nullptr) : nlohmann::json(value);
}

}  // namespace

std::string parse_cpu_model(std::string_view cpuinfo) {
  // x86 says "model name"; arm64 kernels differ by version; POWER says "cpu".
  for (std::string_view wanted : {"model name", "Processor", "cpu model", "Hardware", "cpu"}) {
    std::string found;
    for_each_field(cpuinfo, [&](std::string_view key, std::string_view value) {
      if (found.empty() && key == wanted && !value.empty()) found = value;
    });
    if (!found.empty()) return found;
  }
  return {};
}

std::optional<int> count_processors(std::string_view cpuinfo) {
  int count = 0;
  for_each_field(cpuinfo, [&](std::string_view key, std::string_view) {
    if (key == "processor") ++count;
  });
  return count > 0 ? std::optional<int>(count) : std::nullopt;
}

std::optional<int> count_cpu_list(std::string_view list) {
  list = trim_blanks(list);
  if (list.empty()) return std::nullopt;
  long long count = 0;
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t end = list.find(',', start);
    if (end == std::string_view::npos) end = list.size();
    const std::string_view range = list.substr(start, end - start);
    const auto dash = range.find('-');
    const auto first = parse_integer(range.substr(0, dash));
    const auto last =
        dash == std::string_view::npos ? first : parse_integer(range.substr(dash + 1));
    if (!first || !last || *last < *first || *first < 0) return std::nullopt;
    count += *last - *first + 1;
    start = end + 1;
  }
  return static_cast<int>(count);
}

std::optional<std::uint64_t> parse_mem_total_bytes(std::string_view meminfo) {
  std::optional<std::uint64_t> bytes;
  for_each_field(meminfo, [&](std::string_view key, std::string_view value) {
    if (key != "MemTotal" || bytes) return;
    const auto space = value.find(' ');
    const auto kib = parse_integer(value.substr(0, space));
    if (kib && *kib >= 0) bytes = static_cast<std::uint64_t>(*kib) * 1024u;
  });
  return bytes;
}

std::optional<std::array<double, 3>> parse_load_average(std::string_view loadavg) {
  std::istringstream in{std::string(loadavg)};
  std::array<double, 3> load{};
  if (!(in >> load[0] >> load[1] >> load[2])) return std::nullopt;
  return load;
}

bool is_ci_value(const char* value) {
  if (value == nullptr) return false;
  std::string text(value);
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text == "true" || text == "1";
}

std::string compiler_description() {
#if defined(__clang__)
  return __VERSION__;  // already "Clang x.y.z ..." or "Debian Clang ..."
#elif defined(__GNUC__)
  return std::string("GCC ") + __VERSION__;
#else
  return "unknown";
#endif
}

std::map<int, std::string> cpu_governors(const fs::path& root) {
  std::map<int, std::string> governors;
  std::error_code error;
  for (fs::directory_iterator it(under_root(root, "/sys/devices/system/cpu"), error), end;
       !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (!is_cpu_directory_name(name)) continue;
    if (auto text = read_pseudo_file(it->path() / "cpufreq" / "scaling_governor")) {
      const std::string_view governor = trim_blanks(*text);
      if (!governor.empty()) governors[std::stoi(name.substr(3))] = std::string(governor);
    }
  }
  return governors;
}

MachineContext probe_machine_context(const fs::path& root) {
  MachineContext context;
  if (auto cpuinfo = read_pseudo_file(under_root(root, "/proc/cpuinfo"))) {
    context.cpu_model = parse_cpu_model(*cpuinfo);
    context.logical_cores = count_processors(*cpuinfo);
  }
  if (auto online = read_pseudo_file(under_root(root, "/sys/devices/system/cpu/online"))) {
    context.online_cpus = count_cpu_list(*online);
  }
  context.allowed_cpus = probe_allowed_cpus();
  context.scaling_governors = probe_governors(root);
  context.turbo_enabled = probe_turbo(root);
  context.kernel = probe_kernel();
  context.compiler = compiler_description();
  if (auto loadavg = read_pseudo_file(under_root(root, "/proc/loadavg"))) {
    context.load_average = parse_load_average(*loadavg);
  }
  if (auto meminfo = read_pseudo_file(under_root(root, "/proc/meminfo"))) {
    context.total_memory_bytes = parse_mem_total_bytes(*meminfo);
  }
  context.perf_error = probe_perf_instructions();
  context.perf_instructions_available = context.perf_error.empty();
  if (auto paranoid = read_pseudo_file(under_root(root, "/proc/sys/kernel/perf_event_paranoid"))) {
    if (auto value = parse_integer(*paranoid))
      context.perf_event_paranoid = static_cast<int>(*value);
  }
  context.hostname = probe_hostname();
  context.ci = is_ci_value(std::getenv("CI"));
  return context;
}

void to_json(nlohmann::json& json, const MachineContext& context) {
  json = nlohmann::json{
      {"cpu_model", or_null(context.cpu_model)},
      {"logical_cores", or_null(context.logical_cores)},
      {"online_cpus", or_null(context.online_cpus)},
      {"allowed_cpus", or_null(context.allowed_cpus)},
      {"scaling_governors", context.scaling_governors},
      {"turbo_enabled", or_null(context.turbo_enabled)},
      {"kernel", or_null(context.kernel)},
      {"compiler", or_null(context.compiler)},
      {"load_average", or_null(context.load_average)},
      {"total_memory_bytes", or_null(context.total_memory_bytes)},
      {"perf_instructions_available", context.perf_instructions_available},
      {"perf_error", or_null(context.perf_error)},
      {"perf_event_paranoid", or_null(context.perf_event_paranoid)},
      {"hostname", or_null(context.hostname)},
      {"ci", context.ci},
  };
}

}  // namespace raygate
