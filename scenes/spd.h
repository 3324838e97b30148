// The Standard Procedural Database generators (spd-spec.md §3), as a library: each scene by
// name, with its size factor, written as NFF.
#pragma once

#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include "lib/nff_writer.h"

namespace raygate::scenes {

struct GenerateOptions {
  std::optional<int> size;  // empty: the scene's SPD default
  OutputMode mode = OutputMode::curves;
  int tessellation_resolution = 3;
  int width = 0;  // 0: the scene's own resolution
  int height = 0;
};

struct SceneGenerator {
  std::string_view name;
  std::string_view description;
  int default_size;
  bool uses_size;  // sample and nurbtst ignore the size factor
  void (*generate)(int size, NffWriter& out);
};

// All 13 scenes, in the SPD's order (the seven classic scenes first).
std::span<const SceneGenerator> all_generators();

// nullptr when there is no scene of that name.
const SceneGenerator* find_generator(std::string_view name);

// Largest accepted size factor per scene (keeps output within sane memory); sizes outside
// 1..max_size(name) are rejected with std::invalid_argument naming the valid range.
int max_size(const SceneGenerator& generator);

// Writes the scene as NFF. Throws std::invalid_argument for an unknown name or a bad size.
void generate(std::string_view name, const GenerateOptions& options, std::ostream& out);

}  // namespace raygate::scenes
