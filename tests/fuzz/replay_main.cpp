// The driver of a fuzz target without libFuzzer. Two uses:
//   fuzz_replay_<reader> DIR...      replays every file under the folders through the target: the
//                                    CTest check (label unit) that the committed corpus, the
//                                    crashes and hangs found once included, still passes.
//   fuzz_replay_<reader> --mutate SECONDS --findings DIR [--seed N] CORPUS_DIR...
//                                    fuzzes the target with mutate.h for SECONDS (bench/fuzz/run
//                                    uses it where libFuzzer is not built).
// Exits 0 when every input ran; an escaping exception or a crash ends the process as under the
// fuzzer (mutation mode writes the input first).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "mutate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::string bytes_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::filesystem::path> files_under(const std::vector<std::string>& folders) {
  std::vector<std::filesystem::path> files;
  for (const std::string& folder : folders) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
      if (entry.is_regular_file()) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

struct Options {
  double mutate_seconds = 0.0;  // 0: replay
  std::string findings = "findings";
  std::uint64_t seed = 1;
  std::vector<std::string> folders;
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--mutate" && has_value) {
      options.mutate_seconds = std::atof(argv[++i]);
    } else if (arg == "--findings" && has_value) {
      options.findings = argv[++i];
    } else if (arg == "--seed" && has_value) {
      options.seed = std::strtoull(argv[++i], nullptr, 10);
    } else {
      options.folders.push_back(arg);
    }
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  const std::vector<std::filesystem::path> files = files_under(options.folders);
  if (files.empty()) {
    std::fprintf(stderr, "no corpus files under the folders given\n");
    return 2;
  }
  if (options.mutate_seconds > 0.0) {
    std::vector<std::string> corpus;
    for (const auto& file : files) corpus.push_back(bytes_of(file));
    const raygate::fuzz::MutationRun run =
        raygate::fuzz::mutate_for(&LLVMFuzzerTestOneInput, corpus, options.mutate_seconds,
                                  options.seed, options.findings, 10);
    std::printf("mutated: %llu executions in %.0f s (%.0f/s), no finding\n",
                static_cast<unsigned long long>(run.executions), run.seconds,
                static_cast<double>(run.executions) / std::max(run.seconds, 1e-9));
    return 0;
  }
  const auto started = std::chrono::steady_clock::now();
  for (const std::filesystem::path& file : files) {
    std::fprintf(stderr, "%s\n", file.c_str());
    const std::string data = bytes_of(file);
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("replayed %zu inputs in %.2f s\n", files.size(), seconds);
  return 0;
}
