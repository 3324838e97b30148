// missing_packages asks the real dpkg: one package every Debian system has, one that cannot exist.
#include <gtest/gtest.h>

#include "adapter/adapter.h"
#include "adapter/packages.h"

namespace raygate {
namespace {

Adapter requiring(const std::string& packages) {
  return parse_adapter(R"({"name": "t", "scene_format": "nff", "run": ["t", "{scene}", "{image}"],
    "image": "{image}", "requires": )" +
                           packages + "}",
                       "p.json");
}

TEST(MissingPackages, ReportsOnlyTheOnesNotInstalled) {
  const Adapter a = requiring(R"(["coreutils", "raygate-no-such-package-xyz"])");
  EXPECT_EQ(missing_packages(a), (std::vector<std::string>{"raygate-no-such-package-xyz"}));
}

TEST(MissingPackages, NothingRequiredNothingMissing) {
  EXPECT_TRUE(missing_packages(requiring("[]")).empty());
}

TEST(MissingPackages, AptGetLine) {
  EXPECT_EQ(apt_get_line({"a", "b"}), "apt-get install -y a b");
  EXPECT_EQ(apt_get_line({}), "");
}

}  // namespace
}  // namespace raygate
