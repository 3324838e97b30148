// The fixture tracer's history for the CLI tests of run, compare and bisect: a small real NFF
// ray tracer (tests/fixtures/nff_tracer) and the versions of it each test commits (slower,
// crashing, imageless, ...), plus a tiny two-scene suite.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "checkout/git_fixture.h"
#include "core/fs.h"

namespace raygate::test {

inline const std::filesystem::path kSource(RAYGATE_SOURCE_DIR);
inline const std::filesystem::path kFixture = kSource / "tests" / "fixtures" / "nff_tracer";

// The tracer's source with the one occurrence of `from` replaced by `to`.
inline std::string patched(std::string source, const std::string& from, const std::string& to) {
  const std::size_t at = source.find(from);
  EXPECT_NE(at, std::string::npos) << "fixture tracer.cpp has no '" << from << "'";
  EXPECT_EQ(source.find(from, at + 1), std::string::npos) << "'" << from << "' twice";
  if (at != std::string::npos) source.replace(at, from.size(), to);
  return source;
}

// The tracer at each commit of the fixture history.
struct TracerSources {
  std::string fast = read_file(kFixture / "tracer.cpp");
  // Every pixel traced four times: the same image, about four times the time. A margin this wide
  // keeps the check about behaviour (the ratio follows the tracer), not about timing noise on a
  // loaded CI runner, where two separate runs' ratios of a 0.1 s tracer can differ by 30%.
  std::string slow = patched(fast, "constexpr int kPasses = 1;", "constexpr int kPasses = 4;");
  // Aborts on any scene with spheres (balls), renders the others (tetra).
  std::string crashing = patched(fast, "  const std::vector<unsigned char> pixels = render(scene);",
                                 "  if (!scene.spheres.empty()) std::abort();\n"
                                 "  const std::vector<unsigned char> pixels = render(scene);");
  // Renders, exits 0, and never writes the image.
  std::string imageless = patched(fast, "!write_ppm(argv[3], scene, pixels)", "argv[3] == nullptr");
  // Writes text where the image belongs.
  std::string garbling = patched(fast, "!write_ppm(argv[3], scene, pixels)",
                                 "!(std::ofstream(argv[3]) << \"not an image\\n\")");
  // Sleeps for an hour before rendering.
  std::string hanging = patched(patched(fast, "#include <cmath>\n",
                                        "#include <chrono>\n#include <cmath>\n#include <thread>\n"),
                                "  const Scene scene = parse(in);\n",
                                "  const Scene scene = parse(in);\n"
                                "  std::this_thread::sleep_for(std::chrono::hours(1));\n");
};

// Two scenes small enough for a test (tens of milliseconds each), under the ids of the ci suite
// but with other sizes: the shipped ci goldens are not pictures of them.
inline constexpr const char* kTinySuite = R"({
  "name": "tiny",
  "description": "raygate run's integration test: two small scenes",
  "scenes": [
    {"id": "tetra", "scene": "tetra", "size": 4, "resolution": [128, 128]},
    {"id": "balls", "scene": "balls", "size": 2, "resolution": [128, 128]}
  ]
})";

inline bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A temp dir holding a git repository of the fixture tracer (commits made by the test), a suite
// file, an empty golden folder ("no-goldens") and a cache dir: what every CLI test of the
// measuring commands starts from.
class TracerRepoTest : public ::testing::Test {
 protected:
  explicit TracerRepoTest(const char* suite_json = kTinySuite)
      : repo_(dir_.path() / "tracer-repo") {
    write_file_atomically(suite_, suite_json);
    std::filesystem::create_directories(dir_.path() / "no-goldens");
  }

  // Commits the tracer's `source` and the fixture's Makefile; returns the sha.
  std::string commit(const std::string& source, const std::string& message) {
    repo_.write("tracer.cpp", source);
    repo_.write("Makefile", read_file(kFixture / "Makefile"));
    return repo_.commit(message);
  }

  TempDir dir_;
  testing::GitFixture repo_;
  TracerSources sources_;
  std::filesystem::path suite_ = dir_.path() / "suite.json";
  std::filesystem::path cache_ = dir_.path() / ".raygate";
};

}  // namespace raygate::test
