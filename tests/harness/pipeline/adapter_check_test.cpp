// pipeline/adapter_check: one adapter file checked as `raygate adapter check` does, as values: a
// valid file's summary, an invalid one's error (not thrown, so every file gets its turn), and
// required Debian packages that are missing as a warning with the apt-get line.
#include <gtest/gtest.h>

#include "core/fs.h"
#include "pipeline/adapter_check.h"

namespace raygate {
namespace {

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// An adapter whose run command names `placeholder` and which requires `requires_json`.
std::string adapter_text(const std::string& placeholder, const std::string& requires_json) {
  return R"({"name": "t", "scene_format": "nff", "run": ["t", ")" + placeholder +
         R"("], "image": "{workdir}/a.ppm", "requires": )" + requires_json + "}";
}

class AdapterCheckTest : public ::testing::Test {
 protected:
  // `text` written to dir/name and checked; `file` is then its path.
  AdapterCheck check(const std::string& name, const std::string& text) {
    file = dir.path() / name;
    write_file_atomically(file, text);
    return check_adapter_file(file.string());
  }
  TempDir dir;
  std::filesystem::path file;
};

TEST_F(AdapterCheckTest, AValidFileIsReadBack) {
  const AdapterCheck c = check("plain.json", adapter_text("{scene}", "[]"));
  EXPECT_EQ(c.error, "");
  EXPECT_TRUE(has(c.summary, file.string() + ": ok")) << c.summary;
  EXPECT_EQ(c.warning, "");  // it requires nothing
}

TEST_F(AdapterCheckTest, AnInvalidFileIsAnErrorNotAnException) {
  const AdapterCheck c = check("typo.json", adapter_text("{scen}", "[]"));
  EXPECT_TRUE(has(c.error, "unknown placeholder '{scen}'")) << c.error;
  EXPECT_EQ(c.summary, "");
  EXPECT_TRUE(has(check_adapter_file((dir.path() / "absent.json").string()).error, "absent.json"));
}

TEST_F(AdapterCheckTest, MissingPackagesAreAWarningWithTheAptGetLine) {
  const AdapterCheck c = check(
      "needs.json", adapter_text("{scene}", R"(["coreutils", "raygate-no-such-package-xyz"])"));
  EXPECT_EQ(c.error, "");
  EXPECT_EQ(c.warning, file.string() +
                           ": Debian packages not installed: raygate-no-such-package-xyz\n"
                           "  install them with: apt-get install -y raygate-no-such-package-xyz");
}

}  // namespace
}  // namespace raygate
