// Every ci-suite scene converted to POV-Ray SDL and rendered by Debian's povray: it must parse
// and render without a warning or an error, and show the same scene as raygate-baseline, same
// framing and silhouettes, not mirrored. Compared through the non-background mask of both
// images (intersection over union); shading may differ (docs/scene-formats.md lists where).
// Skipped when povray is not on PATH.
#include <OpenImageIO/imageio.h>
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/fs.h"
#include "core/process.h"
#include "image/image_writer.h"
#include "nff/parser.h"
#include "render/render.h"
#include "spd.h"
#include "writers/scene_writers.h"

namespace raygate::writers {
namespace {

// Measured (docs/scene-formats.md): IoU 1.0 for every ci scene, the masks agree pixel for pixel
// because POV-Ray shoots the baseline's very rays. A mirrored camera gave 0.35-0.999 where the
// background shows; scenes without background (balls, rings, sample) keep IoU 1 even mirrored,
// so the colours decide: the image must be much nearer the baseline's than its mirror image is
// (measured ratio at most 0.24, gears, whose transmitters shade differently).
constexpr double kMinIoU = 0.98;
constexpr double kMaxDifferenceToMirrored = 0.5;

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path != nullptr ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  }
  return false;
}

struct Rgb8 {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> pixels;  // 3 per pixel
};

Rgb8 render_baseline(const nff::Scene& scene) {
  render::RenderStats stats;
  const render::RenderOptions options{render::Accel::bbox};  // the same image as none, faster
  const Image image =
      render::render(render::build_world(scene), render::make_camera(scene.view), options, stats);
  Rgb8 out{image.width, image.height, {}};
  for (float v : image.rgb) out.pixels.push_back(to_8bit(v));
  return out;
}

Rgb8 read_png(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  Rgb8 out{spec.width, spec.height, {}};
  out.pixels.resize(std::size_t(spec.width) * spec.height * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, out.pixels.data())) return {};
  return out;
}

// Mean absolute difference over all channels, in 8-bit steps; with `mirror`, against b seen
// in a mirror (left and right swapped).
double mean_difference(const Rgb8& a, const Rgb8& b, bool mirror) {
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::size_t i = (std::size_t(y) * a.width + x) * 3;
      const std::size_t j = (std::size_t(y) * a.width + (mirror ? a.width - 1 - x : x)) * 3;
      for (int c = 0; c < 3; ++c) sum += std::abs(int(a.pixels[i + c]) - int(b.pixels[j + c]));
    }
  }
  return sum / double(a.pixels.size());
}

struct Agreement {
  double iou = 0.0;                  // of the non-background masks
  std::size_t mask_differences = 0;  // pixels in one mask only
  double identical = 0.0;            // fraction of pixels equal within 1/255 in every channel
};

Agreement compare(const Rgb8& a, const Rgb8& b, const Vec3& background) {
  const unsigned char bg[3] = {to_8bit(float(background.x)), to_8bit(float(background.y)),
                               to_8bit(float(background.z))};
  const auto near = [](int x, int y) { return std::abs(x - y) <= 1; };
  std::size_t both = 0, either = 0, identical = 0;
  const std::size_t n = a.pixels.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char* p = &a.pixels[3 * i];
    const unsigned char* q = &b.pixels[3 * i];
    const bool in_a = !(near(p[0], bg[0]) && near(p[1], bg[1]) && near(p[2], bg[2]));
    const bool in_b = !(near(q[0], bg[0]) && near(q[1], bg[1]) && near(q[2], bg[2]));
    both += in_a && in_b;
    either += in_a || in_b;
    identical += near(p[0], q[0]) && near(p[1], q[1]) && near(p[2], q[2]);
  }
  return {either == 0 ? 1.0 : double(both) / double(either), either - both,
          double(identical) / double(n)};
}

struct SuiteEntry {
  std::string id;
  std::string scene;
  int size = 0;
  int width = 0;
  int height = 0;
};

std::vector<SuiteEntry> ci_suite() {
  std::ifstream in(std::string(RAYGATE_SOURCE_DIR) + "/scenes/suites/ci.json");
  const nlohmann::json suite = nlohmann::json::parse(in);
  std::vector<SuiteEntry> entries;
  for (const nlohmann::json& s : suite.at("scenes")) {
    entries.push_back({s.at("id"), s.at("scene"), s.value("size", 0), s.at("resolution").at(0),
                       s.at("resolution").at(1)});
  }
  return entries;
}

nff::Scene generate(const SuiteEntry& entry) {
  scenes::GenerateOptions options;
  if (entry.size > 0) options.size = entry.size;
  options.width = entry.width;
  options.height = entry.height;
  std::ostringstream text;
  scenes::generate(entry.scene, options, text);
  return nff::parse_nff(text.str(), entry.id + ".nff");
}

TEST(PovRender, CiSuiteMatchesTheBaselinesSilhouettes) {
  if (!on_path("povray")) GTEST_SKIP() << "povray is not on PATH (Debian package povray)";
  const TempDir dir("raygate-pov");
  std::string table;
  for (const SuiteEntry& entry : ci_suite()) {
    SCOPED_TRACE(entry.id);
    const nff::Scene scene = generate(entry);
    write_scene_files(scene, OutputFormat::pov, dir.path() / (entry.id + ".pov"));
    ProcessSpec spec;
    spec.argv = {"povray",
                 "+I" + entry.id + ".pov",
                 "+O" + entry.id + ".png",
                 fmt::format("+W{}", entry.width),
                 fmt::format("+H{}", entry.height),
                 "+FN",
                 "-D",
                 "+WT1",
                 "-GD",
                 "-GR",
                 "-GS",
                 "File_Gamma=1.0"};
    spec.working_directory = dir.path();
    spec.stdout_path = dir.path() / (entry.id + ".log");
    spec.stderr_path = spec.stdout_path;
    spec.timeout = std::chrono::seconds(60);
    Process povray = Process::start(spec);  // renders while the baseline does
    const Rgb8 baseline = render_baseline(scene);
    const ProcessResult result = povray.wait();
    const std::string log = read_file(spec.stdout_path);
    ASSERT_TRUE(result.succeeded()) << result.describe() << "\n" << log;
    EXPECT_EQ(log.find("Warning"), std::string::npos) << log;
    EXPECT_EQ(log.find("Error"), std::string::npos) << log;

    const Rgb8 pov = read_png(dir.path() / (entry.id + ".png"));
    ASSERT_EQ(pov.width, baseline.width);
    ASSERT_EQ(pov.height, baseline.height);
    const Agreement agreement = compare(baseline, pov, scene.background);
    EXPECT_GT(agreement.iou, kMinIoU);
    // Scenes without background (balls, rings, sample) have full masks either way; the colours
    // tell a mirrored image apart.
    const double difference = mean_difference(baseline, pov, false);
    const double mirrored = mean_difference(baseline, pov, true);
    EXPECT_LT(difference, kMaxDifferenceToMirrored * mirrored);
    table +=
        fmt::format("| {} | {}x{} | {:.4f} | {} | {:.1f} % | {:.2f} | {:.2f} | {:.2f} s |\n",
                    entry.id, entry.width, entry.height, agreement.iou, agreement.mask_differences,
                    100.0 * agreement.identical, difference, mirrored, result.wall_seconds);
  }
  std::cout << "| scene | size | IoU | pixels in one mask only | identical pixels | mean diff "
               "| mean diff to mirror | povray wall |\n"
            << table;
}

}  // namespace
}  // namespace raygate::writers
