#include "doctor/system_facts.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <initializer_list>
#include <map>
#include <set>
#include <sstream>

#include "core/fs.h"
#include "core/process.h"
#include "core/text.h"
#include "runner/idle_poll.h"
#include "measure/machine_context.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

std::string trimmed(std::string_view text) { return std::string(trim_blanks(text)); }

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

fs::path under_root(const fs::path& root, std::string_view absolute) {
  return root / fs::path(absolute).relative_path();
}

std::optional<long long> parse_int(std::string_view text) {
  const std::string t = trimmed(text);
  if (t.empty()) return std::nullopt;
  std::size_t used = 0;
  try {
    const long long value = std::stoll(t, &used);
    if (used != t.size()) return std::nullopt;
    return value;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<int> cpu_number(const std::string& name) {
  if (name.size() <= 3 || name.compare(0, 3, "cpu") != 0) return std::nullopt;
  if (!std::all_of(name.begin() + 3, name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  return std::stoi(name.substr(3));
}

// cpuN directories under <root>/sys/devices/system/cpu, ascending by N.
std::map<int, fs::path> cpu_directories(const fs::path& root) {
  std::map<int, fs::path> cpus;
  std::error_code error;
  for (fs::directory_iterator it(under_root(root, "/sys/devices/system/cpu"), error), end;
       !error && it != end; it.increment(error)) {
    if (auto n = cpu_number(it->path().filename().string())) cpus[*n] = it->path();
  }
  return cpus;
}

void probe_cpus(const fs::path& root, SystemFacts& facts) {
  std::set<std::vector<int>> groups;
  for (const auto& [cpu, dir] : cpu_directories(root)) {
    std::error_code error;
    if (fs::is_directory(dir / "cpufreq", error)) facts.cpufreq_present = true;
    if (auto text = read_pseudo_file(dir / "topology" / "thread_siblings_list")) {
      if (auto siblings = parse_cpu_list(*text); siblings.size() > 1) groups.insert(siblings);
    }
  }
  facts.smt_sibling_groups.assign(groups.begin(), groups.end());
  for (const auto& [cpu, governor] : cpu_governors(root)) {
    facts.governors.push_back({cpu, governor});
  }
  if (auto text = read_pseudo_file(under_root(root, "/sys/devices/system/cpu/smt/active"))) {
    if (auto value = parse_int(*text)) facts.smt_active = *value != 0;
  }
}

// One line of output of `systemd-detect-virt FLAG`, or empty ("none", absent, failed).
std::string detect_virt(const std::string& flag) {
  TempDir temp("raygate-doctor");
  ProcessSpec spec;
  spec.argv = {"systemd-detect-virt", flag};
  spec.stdout_path = temp.path() / "out.txt";
  spec.timeout = std::chrono::seconds(10);
  const ProcessResult result = run_process(spec);
  if (!result.succeeded()) return {};
  const std::string answer = trimmed(read_file(spec.stdout_path));
  return answer == "none" ? std::string() : answer;
}

bool has_hypervisor_flag(std::string_view cpuinfo) {
  std::istringstream in{std::string(cpuinfo)};
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("flags", 0) != 0) continue;
    std::istringstream words(
        line.substr(line.find(':') == std::string::npos ? line.size() : line.find(':') + 1));
    for (std::string word; words >> word;) {
      if (word == "hypervisor") return true;
    }
    return false;
  }
  return false;
}

void probe_virtualization(const ProbeOptions& options, SystemFacts& facts) {
  Virtualization& v = facts.virtualization;
  const auto product = read_pseudo_file(under_root(options.root, "/sys/class/dmi/id/product_name"));
  const auto vendor = read_pseudo_file(under_root(options.root, "/sys/class/dmi/id/sys_vendor"));
  if (std::string vm = vm_from_dmi(product.value_or(""), vendor.value_or("")); !vm.empty()) {
    v.vm = vm;
    v.evidence.push_back("DMI product \"" + trimmed(product.value_or("")) + "\", vendor \"" +
                         trimmed(vendor.value_or("")) + "\"");
  }
  if (auto cpuinfo = read_pseudo_file(under_root(options.root, "/proc/cpuinfo"));
      cpuinfo && has_hypervisor_flag(*cpuinfo)) {
    if (v.vm.empty()) v.vm = "unknown hypervisor";
    v.evidence.push_back("CPU flag \"hypervisor\" in /proc/cpuinfo");
  }
  std::error_code error;
  if (fs::exists(under_root(options.root, "/.dockerenv"), error)) {
    v.container = "docker";
    v.evidence.push_back("/.dockerenv exists");
  } else if (fs::exists(under_root(options.root, "/run/.containerenv"), error)) {
    v.container = "podman";
    v.evidence.push_back("/run/.containerenv exists");
  }
  if (auto cgroup = read_pseudo_file(under_root(options.root, "/proc/1/cgroup"))) {
    if (std::string c = container_from_cgroup(*cgroup); !c.empty()) {
      if (v.container.empty()) v.container = c;
      v.evidence.push_back("/proc/1/cgroup names " + c);
    }
  }
  if (!options.live) return;
  if (std::string vm = detect_virt("--vm"); !vm.empty()) {
    v.vm = vm;  // systemd knows more hypervisors than the DMI table above
    v.evidence.push_back("systemd-detect-virt --vm: " + vm);
  }
  if (std::string c = detect_virt("--container"); !c.empty()) {
    v.container = c;
    v.evidence.push_back("systemd-detect-virt --container: " + c);
  }
}

// This process's cgroup path for cgroup v2 ("0::/path") and for v1's cpu controller
// ("4:cpu,cpuacct:/path") from /proc/self/cgroup.
struct CgroupPaths {
  fs::path v2 = "/";
  fs::path v1_cpu = "/";
};

CgroupPaths cgroup_paths(const fs::path& root) {
  CgroupPaths paths;
  const auto text = read_pseudo_file(under_root(root, "/proc/self/cgroup"));
  if (!text) return paths;
  std::istringstream in(*text);
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find(':');
    const auto second = first == std::string::npos ? first : line.find(':', first + 1);
    if (second == std::string::npos) continue;
    const std::string controllers = "," + line.substr(first + 1, second - first - 1) + ",";
    const std::string path = trimmed(line.substr(second + 1));
    if (controllers == ",,") paths.v2 = path;
    if (controllers.find(",cpu,") != std::string::npos) paths.v1_cpu = path;
  }
  return paths;
}

// The tightest quota on the way from `group` up to the root of the hierarchy at `base` (a
// container sees its own cgroup as the root). `read_quota` reads one directory's quota.
template <typename ReadQuota>
std::optional<double> tightest_quota(const fs::path& base, const fs::path& group,
                                     ReadQuota read_quota) {
  std::optional<double> quota;
  for (fs::path dir = group.lexically_normal();; dir = dir.parent_path()) {
    if (auto cpus = read_quota(base / dir.relative_path()); cpus && (!quota || *cpus < *quota)) {
      quota = cpus;
    }
    if (dir.empty() || dir == dir.root_path()) break;
  }
  return quota;
}

std::optional<double> probe_cpu_quota(const fs::path& root) {
  const CgroupPaths paths = cgroup_paths(root);
  auto v2 = tightest_quota(under_root(root, "/sys/fs/cgroup"), paths.v2, [](const fs::path& dir) {
    const auto text = read_pseudo_file(dir / "cpu.max");
    return text ? parse_cpu_max(*text) : std::nullopt;
  });
  if (v2) return v2;
  return tightest_quota(under_root(root, "/sys/fs/cgroup/cpu"), paths.v1_cpu,
                        [](const fs::path& dir) -> std::optional<double> {
                          const auto quota = read_pseudo_file(dir / "cpu.cfs_quota_us");
                          const auto period = read_pseudo_file(dir / "cpu.cfs_period_us");
                          if (!quota || !period) return std::nullopt;
                          return parse_cpu_max(trimmed(*quota) + " " + trimmed(*period));
                        });
}

}  // namespace

std::vector<int> parse_cpu_list(std::string_view list) {
  std::vector<int> cpus;
  std::string text = trimmed(list);
  if (text.empty()) return {};
  std::istringstream in(text);
  for (std::string range; std::getline(in, range, ',');) {
    const auto dash = range.find('-');
    const auto first = parse_int(range.substr(0, dash));
    const auto last = dash == std::string::npos ? first : parse_int(range.substr(dash + 1));
    if (!first || !last || *first < 0 || *last < *first || *last - *first > 65536) return {};
    for (long long cpu = *first; cpu <= *last; ++cpu) cpus.push_back(static_cast<int>(cpu));
  }
  std::sort(cpus.begin(), cpus.end());
  cpus.erase(std::unique(cpus.begin(), cpus.end()), cpus.end());
  return cpus;
}

std::string format_cpu_list(const std::vector<int>& cpus) {
  std::string out;
  for (std::size_t i = 0; i < cpus.size();) {
    std::size_t j = i;
    while (j + 1 < cpus.size() && cpus[j + 1] == cpus[j] + 1) ++j;
    if (!out.empty()) out += ",";
    out +=
        j == i ? std::to_string(cpus[i]) : std::to_string(cpus[i]) + "-" + std::to_string(cpus[j]);
    i = j + 1;
  }
  return out;
}

std::optional<SwapUsage> parse_swap(std::string_view meminfo) {
  std::map<std::string, std::uint64_t> kib;
  std::istringstream in{std::string(meminfo)};
  for (std::string line; std::getline(in, line);) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::istringstream value(line.substr(colon + 1));
    std::uint64_t number = 0;
    if (value >> number) kib[trimmed(line.substr(0, colon))] = number;
  }
  if (!kib.count("SwapTotal") || !kib.count("SwapFree")) return std::nullopt;
  SwapUsage swap;
  swap.total_bytes = kib["SwapTotal"] * 1024u;
  const std::uint64_t free_bytes = kib["SwapFree"] * 1024u;
  swap.used_bytes = swap.total_bytes > free_bytes ? swap.total_bytes - free_bytes : 0;
  if (kib.count("MemAvailable")) swap.available_memory_bytes = kib["MemAvailable"] * 1024u;
  return swap;
}

std::optional<double> parse_cpu_max(std::string_view cpu_max) {
  std::istringstream in{std::string(cpu_max)};
  std::string quota;
  double period = 0.0;
  if (!(in >> quota >> period) || quota == "max" || !(period > 0.0)) return std::nullopt;
  const auto quota_us = parse_int(quota);
  if (!quota_us || *quota_us <= 0) return std::nullopt;
  return static_cast<double>(*quota_us) / period;
}

std::optional<CpuTimes> parse_cpu_times(std::string_view proc_stat) {
  std::istringstream in{std::string(proc_stat)};
  std::string label;
  if (!(in >> label) || label != "cpu") return std::nullopt;
  CpuTimes times;
  std::uint64_t value = 0;
  int field = 0;
  // user nice system idle iowait irq softirq steal guest guest_nice; guest time is already
  // counted in user and nice, so only the first eight make the total.
  while (field < 8 && in >> value) {
    times.total += value;
    if (field == 7) times.steal = value;
    ++field;
  }
  if (field < 4) return std::nullopt;
  return times;
}

namespace {

using KnownNames = std::initializer_list<std::pair<std::string_view, std::string_view>>;

// The name of the first needle found in `text` (lower case), or "".
std::string first_known(const std::string& text, KnownNames known) {
  for (const auto& [needle, name] : known) {
    if (text.find(needle) != std::string::npos) return std::string(name);
  }
  return {};
}

}  // namespace

std::string vm_from_dmi(std::string_view product_name, std::string_view sys_vendor) {
  return first_known(lower(trimmed(product_name)) + " | " + lower(trimmed(sys_vendor)),
                     {{"kvm", "kvm"},
                      {"qemu", "qemu"},
                      {"standard pc (", "qemu"},
                      {"vmware", "vmware"},
                      {"virtualbox", "oracle"},
                      {"hvm domu", "xen"},
                      {"xen", "xen"},
                      {"virtual machine", "microsoft"},
                      {"google compute engine", "google"},
                      {"amazon ec2", "amazon"},
                      {"openstack", "openstack"},
                      {"bochs", "bochs"},
                      {"parallels", "parallels"},
                      {"bhyve", "bhyve"}});
}

std::string container_from_cgroup(std::string_view cgroup) {
  return first_known(lower(cgroup), {{"kubepods", "kubernetes"},
                                     {"docker", "docker"},
                                     {"libpod", "podman"},
                                     {"lxc", "lxc"},
                                     {"containerd", "containerd"}});
}

std::optional<CpuTimes> read_cpu_times(const fs::path& root) {
  const auto text = read_pseudo_file(under_root(root, "/proc/stat"));
  return text ? parse_cpu_times(*text) : std::nullopt;
}

SystemFacts probe_system_facts(const ProbeOptions& options) {
  SystemFacts facts;
  facts.machine = probe_machine_context(options.root);
  probe_cpus(options.root, facts);
  if (options.live) facts.allowed_cpus = allowed_cpu_list();
  if (auto text =
          read_pseudo_file(under_root(options.root, "/proc/sys/kernel/randomize_va_space"))) {
    if (auto value = parse_int(*text)) facts.aslr = static_cast<int>(*value);
  }
  if (auto text = read_pseudo_file(under_root(options.root, "/proc/meminfo")))
    facts.swap = parse_swap(*text);
  facts.cpu_quota = probe_cpu_quota(options.root);
  probe_virtualization(options, facts);
  if (options.live) {
    const IdlePollHold hold(kCpuLatencyDevice);  // asked and let go at once
    facts.idle_polling = IdlePolling{hold.held(), hold.why_not()};
  }
  return facts;
}

}  // namespace raygate
