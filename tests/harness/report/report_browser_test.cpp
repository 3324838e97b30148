// The HTML report in a real browser: headless Chromium renders it to a screenshot that is not
// blank, logs no console message (no script error), and the page's script runs (it marks the
// body data-js="ready"). Skipped where Chromium is not installed (ci/install-deps installs it).
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <cstdlib>
#include <fstream>
#include <set>

#include "core/process.h"
#include "report_fixture.h"

namespace raygate::test {
namespace {

namespace OIIO = OIIO_NAMESPACE;

std::filesystem::path find_chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    for (const char* dir : {"/usr/bin", "/usr/local/bin", "/snap/bin"}) {
      const std::filesystem::path path = std::filesystem::path(dir) / name;
      if (std::filesystem::exists(path)) return path;
    }
  }
  return {};
}

struct Browser {
  std::filesystem::path exe;
  std::filesystem::path dir;

  // Runs headless Chromium on `page` with extra flags; returns what it printed.
  std::string run(const std::filesystem::path& page, std::vector<std::string> flags,
                  const std::string& name) const {
    ProcessSpec spec;
    spec.argv = {exe.string(),
                 "--headless",
                 "--no-sandbox",
                 "--disable-gpu",
                 "--no-first-run",
                 "--disable-extensions",
                 "--user-data-dir=" + (dir / "profile").string()};
    spec.argv.insert(spec.argv.end(), flags.begin(), flags.end());
    spec.argv.push_back("file://" + page.string());
    spec.stdout_path = dir / (name + ".out");
    spec.stderr_path = dir / (name + ".err");
    spec.timeout = std::chrono::seconds(90);
    const ProcessResult result = run_process(spec);
    EXPECT_TRUE(result.succeeded()) << result.describe() << "\n" << read_file(spec.stderr_path);
    return read_file(spec.stdout_path) + read_file(spec.stderr_path);
  }
};

std::set<std::uint32_t> colours_of(const std::filesystem::path& png, double& white_fraction) {
  OIIO::ImageBuf image(png.string());
  EXPECT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::UINT8)) << image.geterror();
  std::set<std::uint32_t> colours;
  long white = 0, pixels = 0;
  for (OIIO::ImageBuf::ConstIterator<unsigned char> it(image); !it.done(); ++it, ++pixels) {
    const std::uint32_t rgb = (std::uint32_t(it[0] * 255.f) << 16) |
                              (std::uint32_t(it[1] * 255.f) << 8) | std::uint32_t(it[2] * 255.f);
    if (rgb == 0xFFFFFFu) ++white;
    if (colours.size() < 10000) colours.insert(rgb);
  }
  white_fraction = pixels > 0 ? static_cast<double>(white) / static_cast<double>(pixels) : 1.0;
  return colours;
}

TEST(ReportBrowser, RendersWithoutErrors) {
  const std::filesystem::path chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium)";
  Fixture f(true);
  f.input->trends.push_back(make_trend("mount", 16));
  // Kept in the build folder, page and screenshot, for a person to look at.
  const std::filesystem::path page = std::filesystem::path(RAYGATE_BINARY_DIR) / "report-test.html";
  const std::filesystem::path shot = std::filesystem::path(RAYGATE_BINARY_DIR) / "report-test.png";
  std::ofstream(page) << f.render("html");
  std::filesystem::remove(shot);
  const Browser browser{chromium, f.dir.path()};

  const std::string log = browser.run(page,
                                      {"--enable-logging=stderr", "--v=0", "--hide-scrollbars",
                                       "--window-size=1280,2000", "--screenshot=" + shot.string()},
                                      "screenshot");
  EXPECT_EQ(log.find("Uncaught"), std::string::npos) << log;
  EXPECT_EQ(log.find(":CONSOLE"), std::string::npos) << "the page logged to the console:\n" << log;
  ASSERT_TRUE(std::filesystem::exists(shot)) << log;

  double white = 1.0;
  const std::set<std::uint32_t> colours = colours_of(shot, white);
  EXPECT_GT(colours.size(), 200u) << "text, badges and images give many colours";
  EXPECT_LT(white, 0.9) << "the page is not blank";

  const std::string dom = browser.run(page, {"--dump-dom"}, "dom");
  EXPECT_NE(dom.find(R"(<body data-js="ready">)"), std::string::npos) << "the script ran";
}

}  // namespace
}  // namespace raygate::test
