// The scene registry: names, defaults, size validation and the suites' resolution override.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

#include "nff/parser.h"
#include "nff_summary.h"
#include "spd.h"

namespace raygate::scenes {
namespace {

std::string generate_text(const std::string& name, GenerateOptions options = {}) {
  std::ostringstream out;
  generate(name, options, out);
  return out.str();
}

std::string error_of(const std::string& name, GenerateOptions options) {
  try {
    generate_text(name, options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(SceneRegistry, ListsAllThirteenScenesInSpdOrder) {
  std::vector<std::string> names;
  for (const SceneGenerator& g : all_generators()) names.emplace_back(g.name);
  EXPECT_EQ(names, (std::vector<std::string>{"balls", "gears", "mount", "rings", "teapot", "tetra",
                                             "tree", "lattice", "shells", "jacks", "sombrero",
                                             "sample", "nurbtst"}));
  EXPECT_EQ(find_generator("teapot")->default_size, 6);
  EXPECT_EQ(find_generator("nope"), nullptr);
}

TEST(SceneRegistry, DefaultSizeIsTheSpdDefault) {
  GenerateOptions four;
  four.size = 4;
  EXPECT_EQ(generate_text("balls"), generate_text("balls", four));
}

TEST(SceneRegistry, BadSizesAreClearErrors) {
  GenerateOptions options;
  for (const int size : {0, -3, 7, 1000000}) {
    options.size = size;
    EXPECT_EQ(error_of("balls", options),
              "scene 'balls': size " + std::to_string(size) + " is out of range 1..6");
  }
  options.size = 8;
  EXPECT_EQ(error_of("mount", options), "scene 'mount': size 8 is out of range 1..7");
  EXPECT_NE(error_of("ballz", {}).find("unknown scene 'ballz'"), std::string::npos);
  GenerateOptions tessellated;
  tessellated.mode = OutputMode::tessellated;
  tessellated.tessellation_resolution = 0;
  EXPECT_NE(error_of("balls", tessellated).find("tessellation resolution 0"), std::string::npos);
}

TEST(SceneRegistry, ResolutionOverrideChangesOnlyTheResolutionLine) {
  GenerateOptions small;
  small.width = 96;
  small.height = 64;
  const auto base = test::summarize_nff(generate_text("tetra"));
  const auto resized = test::summarize_nff(generate_text("tetra", small));
  EXPECT_EQ(resized.view_lines[5], "resolution 96 64");
  EXPECT_EQ(resized.polygons, base.polygons);
  EXPECT_EQ(std::vector<std::string>(resized.view_lines.begin(), resized.view_lines.begin() + 5),
            std::vector<std::string>(base.view_lines.begin(), base.view_lines.begin() + 5));
  small.width = 20000;
  EXPECT_NE(error_of("tetra", small).find("out of range"), std::string::npos);
}

// The generators and the reader agree: every scene the SPD can make loads, with the counts the
// generator wrote (the SPD's teapot at size 1 has zero-area patches; they must load too).
TEST(SceneRegistry, EveryGeneratedSceneLoadsInTheReader) {
  for (const SceneGenerator& g : all_generators()) {
    for (const int size : {1, 2, 3, 0}) {
      GenerateOptions options;
      if (size > 0) options.size = size;
      const std::string text = generate_text(std::string(g.name), options);
      const std::string label = std::string(g.name) + " size " + std::to_string(size);
      try {
        const nff::Scene scene = nff::parse_nff(text, label);
        const auto summary = test::summarize_nff(text);
        EXPECT_EQ(static_cast<long>(scene.spheres.size()), summary.spheres) << label;
        EXPECT_EQ(static_cast<long>(scene.polygons.size()), summary.polygons) << label;
        EXPECT_EQ(static_cast<long>(scene.patches.size()), summary.patches) << label;
        EXPECT_EQ(static_cast<long>(scene.lights.size()), summary.lights) << label;
      } catch (const nff::ParseError& e) {
        ADD_FAILURE() << e.what();
      }
    }
  }
}

}  // namespace
}  // namespace raygate::scenes
