// Shared set-up of the builder tests: a temp dir holding a fake worktree, a cache and a counter
// file, and toy adapters whose build steps are small sh scripts. (raygate itself never uses a
// shell; only these test adapters do, to create files and count how often a step ran.)
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "adapter/adapter.h"
#include "builder/builder.h"
#include "checkout/worktree.h"
#include "core/fs.h"

namespace raygate::testing {

inline const std::string kShaA = "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa";
inline const std::string kShaB = "bbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbb";

// `steps` is the adapter's "build" array; `extra` holds more members of the adapter object.
// (A vector rather than a json initializer list, which could turn a two-word step into an object.)
inline Adapter toy_adapter(const std::vector<nlohmann::json>& steps,
                           const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json doc = {{"name", "toy"},
                        {"scene_format", "nff"},
                        {"run", {"{build}/tracer", "{scene}", "{image}"}},
                        {"image", "{image}"},
                        {"build", steps}};
  doc.update(extra);
  return parse_adapter(doc.dump(), "toy.json");
}

// A step that appends a line to `counter`, so a test can see how many times it ran.
inline nlohmann::json count_step(const std::filesystem::path& counter) {
  return {"sh", "-c", "echo ran >> \"$1\"", "sh", counter.string()};
}

inline int lines_in(const std::filesystem::path& file) {
  std::ifstream in(file);
  int n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

class BuilderFixture {
 public:
  BuilderFixture() { std::filesystem::create_directories(tree()); }
  std::filesystem::path root() const { return dir_.path(); }
  std::filesystem::path tree() const { return dir_.path() / "tree"; }
  std::filesystem::path cache() const { return dir_.path() / "cache"; }
  std::filesystem::path counter() const { return dir_.path() / "counter.txt"; }

  Worktree worktree(const std::string& sha = kShaA, bool dirty = false) const {
    Worktree w;
    w.path = tree();
    w.sha = sha;
    w.short_sha = sha.substr(0, 7);
    w.dirty = dirty;
    return w;
  }

  BuildOptions options(const std::string& compiler = "test compiler 1.0") const {
    BuildOptions o;
    o.cache_dir = cache();
    o.raygate_source = dir_.path() / "raygate-src";
    o.jobs = 3;
    o.compiler_identity = compiler;
    return o;
  }

 private:
  TempDir dir_{"raygate-builder-test"};
};

}  // namespace raygate::testing
