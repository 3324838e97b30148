#include "mutate.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstring>
#include <exception>
#include <random>
#include <string_view>

namespace raygate::fuzz {

namespace {

// What a dying process writes: the input it was running. Static because a signal handler can
// reach nothing else; set before each execution.
struct CurrentInput {
  const char* data = nullptr;
  std::size_t size = 0;
  char path[4096] = {};
};
CurrentInput g_current;  // NOLINT: only a signal handler's state

void write_current_input() {
  const int fd = ::open(g_current.path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return;
  std::size_t done = 0;
  while (done < g_current.size) {
    const ssize_t n = ::write(fd, g_current.data + done, g_current.size - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
  static const char note[] = "fuzz: finding written to ";
  [[maybe_unused]] ssize_t ignored = ::write(2, note, sizeof note - 1);
  ignored = ::write(2, g_current.path, std::strlen(g_current.path));
  ignored = ::write(2, "\n", 1);
}

void on_fatal_signal(int signal) {
  write_current_input();
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

void on_terminate() {
  static const char note[] = "fuzz: an exception escaped the target\n";
  [[maybe_unused]] const ssize_t ignored = ::write(2, note, sizeof note - 1);
  write_current_input();
  std::_Exit(134);
}

// Where input goes wrong in files people write and strangers send.
constexpr std::array<std::string_view, 28> kTokens = {"1e400",
                                                      "-1e400",
                                                      "-1",
                                                      "0",
                                                      "1e-400",
                                                      "0.5",
                                                      "NaN",
                                                      "Infinity",
                                                      "null",
                                                      "true",
                                                      "false",
                                                      "\"\"",
                                                      "\"x\"",
                                                      "{",
                                                      "}",
                                                      "[",
                                                      "]",
                                                      ",",
                                                      ":",
                                                      "\"",
                                                      "\\u0000",
                                                      "18446744073709551616",
                                                      "-9223372036854775809",
                                                      "99999999999",
                                                      "\\ud800",
                                                      "{}",
                                                      "[]",
                                                      "\n"};

class Mutator {
 public:
  Mutator(const std::vector<std::string>& corpus, std::uint64_t seed)
      : corpus_(corpus), random_(seed) {}

  std::string next() {
    std::string input = corpus_[pick(corpus_.size())];
    const std::size_t changes = 1 + pick(4);
    for (std::size_t i = 0; i < changes; ++i) mutate(input);
    constexpr std::size_t kMaxBytes = 1 << 16;
    if (input.size() > kMaxBytes) input.resize(kMaxBytes);
    return input;
  }

 private:
  std::size_t pick(std::size_t n) {
    return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
  }

  void mutate(std::string& s) {
    const std::size_t at = pick(s.size() + 1);
    switch (pick(9)) {
      case 0:
        if (!s.empty()) s[pick(s.size())] ^= static_cast<char>(1u << pick(8));
        break;
      case 1:
        if (!s.empty()) s[pick(s.size())] = static_cast<char>(pick(256));
        break;
      case 2: s.insert(at, 1, static_cast<char>(pick(256))); break;
      case 3:
        if (at < s.size()) s.erase(at, 1 + pick(std::min<std::size_t>(s.size() - at, 64)));
        break;
      case 4:
        if (at < s.size()) {
          const std::string piece = s.substr(at, 1 + pick(64));
          s.insert(pick(s.size() + 1), piece);
        }
        break;
      case 5: {
        const std::string& other = corpus_[pick(corpus_.size())];
        const std::size_t from = pick(other.size() + 1);
        s.insert(at, other.substr(from, pick(256)));
        break;
      }
      case 6: s.insert(at, kTokens[pick(kTokens.size())]); break;
      case 7: replace_number(s); break;
      default: replace_word(s); break;
    }
  }

  // A number in the text becomes a token: the reader's range checks are where it hurts.
  void replace_number(std::string& s) {
    const std::size_t start = s.find_first_of("0123456789", pick(s.size() + 1));
    if (start == std::string::npos) return;
    const std::size_t end = s.find_first_not_of("0123456789.eE+-", start);
    s.replace(start, (end == std::string::npos ? s.size() : end) - start, kTokens[pick(12)]);
  }

  // A quoted word becomes another input's quoted word: known keys in unknown places, values of
  // one field in another.
  void replace_word(std::string& s) {
    const std::size_t open = s.find('"', pick(s.size() + 1));
    if (open == std::string::npos) return;
    const std::size_t close = s.find('"', open + 1);
    if (close == std::string::npos) return;
    const std::string& other = corpus_[pick(corpus_.size())];
    const std::size_t other_open = other.find('"', pick(other.size() + 1));
    if (other_open == std::string::npos) return;
    const std::size_t other_close = other.find('"', other_open + 1);
    if (other_close == std::string::npos) return;
    s.replace(open, close - open + 1, other.substr(other_open, other_close - other_open + 1));
  }

  const std::vector<std::string>& corpus_;
  std::mt19937_64 random_;
};

}  // namespace

MutationRun mutate_for(int (*target)(const std::uint8_t*, std::size_t),
                       const std::vector<std::string>& corpus, double seconds, std::uint64_t seed,
                       const std::filesystem::path& findings, unsigned timeout_seconds) {
  std::filesystem::create_directories(findings);
  const std::string path = (findings / ("crash-" + std::to_string(::getpid()))).string();
  std::strncpy(g_current.path, path.c_str(), sizeof g_current.path - 1);
  for (const int signal : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL, SIGALRM}) {
    ::signal(signal, on_fatal_signal);
  }
  std::set_terminate(on_terminate);
  Mutator mutator(corpus, seed);
  MutationRun run;
  const auto started = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  while (elapsed() < seconds) {
    const std::string input = mutator.next();
    g_current.data = input.data();
    g_current.size = input.size();
    ::alarm(timeout_seconds);  // a hang is a finding too
    target(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
    ::alarm(0);
    ++run.executions;
  }
  run.seconds = elapsed();
  return run;
}

}  // namespace raygate::fuzz
