// `raygate report`, run as a user would: each format from a stored document, the gate's exit
// code only on request, and usage errors for bad input.
#include <gtest/gtest.h>

#include <pugixml.hpp>

#include "../cli/cli_support.h"
#include "report_fixture.h"

namespace raygate::test {
namespace {

struct StoredDocument {
  TempDir dir{"raygate-report-cli"};
  StoredDocument() { write_results(make_compare_document(dir.path()), dir.path() / "doc.json"); }
};

TEST(ReportCli, ConsoleToStandardOutput) {
  const StoredDocument doc;
  const CliRun r = run_raygate({"report", "doc.json"}, doc.dir);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("raygate: 2 regressions (mount +7.9%"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\033'), std::string::npos) << "not a terminal: no colour";
}

TEST(ReportCli, ExitCodeOnRequest) {
  const StoredDocument doc;
  EXPECT_EQ(run_raygate({"report", "doc.json", "--exit-code"}, doc.dir).exit_code, 1);
}

TEST(ReportCli, EveryFormatToAFile) {
  const StoredDocument doc;
  for (const char* format : {"markdown", "junit", "json", "html"}) {
    const std::string file = std::string("report.") + format;
    const CliRun r = run_raygate({"report", "doc.json", "--format", format, "-o", file}, doc.dir);
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.out;
    EXPECT_GT(std::filesystem::file_size(doc.dir.path() / file), 500u) << format;
  }
  pugi::xml_document xml;
  EXPECT_TRUE(xml.load_file((doc.dir.path() / "report.junit").c_str()));
  const auto json = nlohmann::json::parse(read_file(doc.dir.path() / "report.json"));
  EXPECT_EQ(json.at("exit_code"), 1);
  EXPECT_NE(read_file(doc.dir.path() / "report.html").find("data:image/png;base64,"),
            std::string::npos);
}

TEST(ReportCli, PolicyChangesTheVerdict) {
  const StoredDocument doc;
  write_file_atomically(doc.dir.path() / "policy.json",
                        R"({"scenes": {"mount": {"max_slowdown": 0.10,
                            "reason": "known slow path, tracked in #12"}}})");
  const CliRun r = run_raygate(
      {"report", "doc.json", "--policy", "policy.json", "--format", "json", "-o", "r.json"},
      doc.dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto json = nlohmann::json::parse(read_file(doc.dir.path() / "r.json"));
  EXPECT_EQ(json.at("counts").at("fail"), 1) << json.dump(1);  // only gears' image now
}

// Without --policy, a report judges by the limits the document was measured under, as `gate`
// does: a compare at a 10% limit is not re-judged at the built-in 3% (the report and the compare
// that wrote the document must not disagree).
TEST(ReportCli, RecordedLimitsJudgeAsTheGateDoes) {
  TempDir dir{"raygate-report-cli"};
  ResultsDocument document = make_compare_document(dir.path());
  document.settings.max_slowdown = 0.10;
  write_results(document, dir.path() / "doc.json");
  const CliRun report = run_raygate({"report", "doc.json"}, dir);
  EXPECT_NE(report.out.find("raygate: 1 regression (gears"), std::string::npos) << report.out;
  const CliRun gate = run_raygate({"gate", "doc.json"}, dir);
  EXPECT_NE(gate.out.find("4 scenes, 1 failed"), std::string::npos) << gate.out;
}

TEST(ReportCli, BadInputIsAUsageError) {
  const StoredDocument doc;
  EXPECT_EQ(run_raygate({"report", "doc.json", "--format", "pdf"}, doc.dir).exit_code, 2);
  EXPECT_EQ(run_raygate({"report", "missing.json"}, doc.dir).exit_code, 2);
  // A report written over the document it reports on would lose the document.
  const std::string before = read_file(doc.dir.path() / "doc.json");
  const CliRun over =
      run_raygate({"report", "doc.json", "--format", "json", "-o", "doc.json"}, doc.dir);
  EXPECT_EQ(over.exit_code, 2) << over.out;
  EXPECT_NE(over.out.find("name the same file"), std::string::npos) << over.out;
  EXPECT_EQ(read_file(doc.dir.path() / "doc.json"), before);
  write_file_atomically(doc.dir.path() / "bad.json", R"({"kind": "run"})");
  const CliRun r = run_raygate({"report", "bad.json"}, doc.dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("not a raygate results document"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace raygate::test
