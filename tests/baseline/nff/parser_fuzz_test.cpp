// Mutated input for the NFF reader: random byte edits, token splices and truncations of a
// valid scene (fixed seed) must either parse into a consistent scene or throw a ParseError with
// a well-formed, printable message. Anything else (a crash, another exception, a sanitizer
// report under the asan preset) fails.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <regex>
#include <string>

#include "nff/parser.h"

namespace raygate::nff {
namespace {

constexpr const char* kSeedScene =
    "b 0.078 0.361 0.753\n"
    "v\nfrom -1.1 -2.1 2.6\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\nresolution 64 48\n"
    "l 2 4 4\nl -2 4 3 0.5 0.5 0.5\n"
    "f 1 0.85 0.7 0.3 0.6 3.0827 0 0 # ground\n"
    "p 4\n2 2 0\n-2 2 0\n-2 -2 0\n2 -2 0\n"
    "f 0.5 0.45 0.35 1 0 0 0 0\n"
    "s -0.8 0.8 1.20821 0.17\n"
    "c 0 0 0 0.15 0 0 1 0.1005\n"
    "c\n1 1 1 0.5\n1 1 2 0.25\n"
    "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 -0.267261 0.534522 0.801784\n"
    "p 6\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n";

// Pieces that push the reader into its edge cases when spliced in.
constexpr std::array<const char*, 22> kSplices = {"nan",       "1e999",
                                                  "-0",        "p",
                                                  "pp",        "p 2000000000",
                                                  "v",         "#",
                                                  "\n",        " ",
                                                  "s",         "c",
                                                  "f",         "l",
                                                  "1e-999",    "+",
                                                  "-",         ".",
                                                  "from",      "resolution 0 0",
                                                  "angle 180", "0x1p3"};

std::string mutate(std::string text, std::mt19937& random) {
  auto pick = [&](std::size_t bound) {
    return bound == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, bound - 1)(random);
  };
  const std::size_t edits = 1 + pick(3);
  for (std::size_t e = 0; e < edits && !text.empty(); ++e) {
    const std::size_t at = pick(text.size());
    switch (pick(6)) {
      case 0:  // any byte, control and high bytes included
        text[at] = static_cast<char>(pick(256));
        break;
      case 1: {  // a plausible character
        static constexpr char kPlausible[] = "0123456789.-+eE #\n\tpsvcfl";
        text[at] = kPlausible[pick(sizeof kPlausible - 1)];
        break;
      }
      case 2:  // delete a short range
        text.erase(at, 1 + pick(8));
        break;
      case 3:  // duplicate a short range
        text.insert(at, text.substr(at, 1 + pick(12)));
        break;
      case 4:  // splice a token
        text.insert(at, std::string(" ") + kSplices[pick(kSplices.size())] + " ");
        break;
      default:  // truncate
        text.resize(at);
        break;
    }
  }
  return text;
}

// What a parsed scene must satisfy whatever the input was.
void check_scene(const Scene& scene) {
  const auto material_ok = [&](int m) {
    return m >= 0 && m < static_cast<int>(scene.materials.size());
  };
  EXPECT_TRUE(is_finite(scene.view.from) && is_finite(scene.view.at) && is_finite(scene.view.up));
  EXPECT_GT(scene.view.angle_degrees, 0.0);
  EXPECT_LT(scene.view.angle_degrees, 180.0);
  for (const Sphere& s : scene.spheres) {
    EXPECT_TRUE(material_ok(s.material));
    EXPECT_NE(s.radius, 0.0);
  }
  for (const Cone& c : scene.cones) EXPECT_TRUE(material_ok(c.material));
  for (const Polygon& p : scene.polygons) {
    EXPECT_TRUE(material_ok(p.material));
    EXPECT_GE(p.vertices.size(), 3u);
  }
  for (const Patch& p : scene.patches) {
    EXPECT_TRUE(material_ok(p.material));
    EXPECT_EQ(p.vertices.size(), p.normals.size());
  }
}

void check_error(const ParseError& error, const std::string& text) {
  static const std::regex shape(R"(fuzz\.nff:[0-9]+:[0-9]+: expected .+, found .+)");
  const std::string message = error.what();
  EXPECT_TRUE(std::regex_match(message, shape)) << message;
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    ASSERT_TRUE(byte >= 0x20 && byte < 0x7f) << "raw byte in message: " << message;
  }
  long lines = 1;
  for (const char c : text) lines += c == '\n' ? 1 : 0;
  EXPECT_GE(error.loc().line, 1);
  EXPECT_LE(error.loc().line, lines);
  EXPECT_GE(error.loc().column, 1);
  EXPECT_LE(error.loc().column, static_cast<int>(text.size()) + 1);
}

TEST(NffParserFuzz, MutationsParseOrFailCleanly) {
  ASSERT_NO_THROW(parse_nff(kSeedScene, "fuzz.nff"));
  std::mt19937 random(20240521);
  int parsed = 0;
  int rejected = 0;
  for (int i = 0; i < 4000; ++i) {
    const std::string text = mutate(kSeedScene, random);
    try {
      check_scene(parse_nff(text, "fuzz.nff"));
      ++parsed;
    } catch (const ParseError& error) {
      check_error(error, text);
      ++rejected;
    } catch (const std::exception& other) {
      ADD_FAILURE() << "unexpected exception " << other.what() << " for input:\n" << text;
    }
    if (HasFailure()) {
      ADD_FAILURE() << "case " << i << " input:\n" << text;
      return;
    }
  }
  // The mutations must exercise both outcomes, or the test proves little.
  EXPECT_GT(parsed, 200);
  EXPECT_GT(rejected, 2000);
  std::printf("%d parsed, %d rejected\n", parsed, rejected);
}

// Every prefix of the scene: truncation at each byte.
TEST(NffParserFuzz, EveryTruncation) {
  const std::string scene = kSeedScene;
  for (std::size_t length = 0; length < scene.size(); ++length) {
    const std::string text = scene.substr(0, length);
    try {
      check_scene(parse_nff(text, "fuzz.nff"));
    } catch (const ParseError& error) {
      check_error(error, text);
    }
    if (HasFailure()) {
      ADD_FAILURE() << "truncated at " << length;
      return;
    }
  }
}

}  // namespace
}  // namespace raygate::nff
