#include "fuzz_input.h"

#include <stdlib.h>

#include <cstdio>
#include <stdexcept>

namespace raygate::fuzz {

namespace {

// One folder for the process's life; removed at exit (the folder is small and per process).
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "raygate-fuzz-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace

std::filesystem::path scratch_file(std::string_view text, const std::string& name) {
  static const ScratchDir dir;
  const std::filesystem::path path = dir.path() / name;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) throw std::runtime_error("cannot write " + path.string());
  const std::size_t written = std::fwrite(text.data(), 1, text.size(), file);
  std::fclose(file);
  if (written != text.size()) throw std::runtime_error("short write to " + path.string());
  return path;
}

}  // namespace raygate::fuzz
