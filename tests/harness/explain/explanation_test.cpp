// The per-function profile of a cachegrind file (explain/function_profile.h) and the explanation
// of a change (explain/explanation.h), on hand-written fixtures whose sums are worked out here:
// base and head differ in shade() (+7000 instructions), a new sky() (+400) and memcpy (-50).
#include "explain/explanation.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/fs.h"
#include "explain/function_profile.h"

namespace raygate {
namespace {

const std::filesystem::path kFixtures =
    std::filesystem::path(RAYGATE_SOURCE_DIR) / "tests" / "fixtures" / "cachegrind";

FunctionProfile fixture(const std::string& name) {
  return parse_function_profile(read_file(kFixtures / name), name);
}

TEST(FunctionProfile, SumsSelfCostPerFunctionAndDemangles) {
  const FunctionProfile base = fixture("functions_base.cg");
  ASSERT_EQ(base.size(), 4u);
  const FunctionCost& traverse =
      base.at("bvh::traverse(Ray const&)");  // from _ZN3bvh8traverseERK3Ray
  EXPECT_EQ(traverse.file, "src/bvh.cpp");
  EXPECT_EQ(traverse.self.ir, 1500u);
  EXPECT_EQ(traverse.self.dr, 600u);
  EXPECT_EQ(traverse.self.d1mr, 30u);
  EXPECT_EQ(traverse.self.dlmr, 1u);  // the second line left its trailing zeros out
  EXPECT_EQ(traverse.self.dw, 100u);
  EXPECT_DOUBLE_EQ(estimated_cycles(traverse.self), 1500 + 10 * 31 + 100 * 1);
  EXPECT_EQ(base.at("shade(Hit const&)").self.ir, 3000u);
  EXPECT_EQ(base.at("memcpy").file, "???");
}

TEST(FunctionProfile, DemanglesOnlyMangledNames) {
  EXPECT_EQ(demangled("_ZN3bvh8traverseERK3Ray"), "bvh::traverse(Ray const&)");
  EXPECT_EQ(demangled("main"), "main");
  EXPECT_EQ(demangled("_Znot-a-valid-name"), "_Znot-a-valid-name");
}

TEST(FunctionProfile, RefusesMalformedFilesWithTheirLine) {
  const std::string events = "events: Ir Dr\n";
  EXPECT_THROW(parse_function_profile("fn=main\n1 2\n", "x.cg"), InfraError);  // no events
  try {
    parse_function_profile(events + "fl=a.c\n3 4 5\n", "x.cg");
    FAIL() << "a cost line before fn= was accepted";
  } catch (const InfraError& e) {
    EXPECT_NE(std::string(e.what()).find("x.cg:3: a cost line before any 'fn=' line"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parse_function_profile(events + "fn=f\n1 2 3 4\n", "x.cg"), InfraError);
  EXPECT_THROW(parse_function_profile(events + "fn=f\n1 2x\n", "x.cg"), InfraError);
}

TEST(FunctionProfile, ReadsAndSumsEveryProcessFileOfARun) {
  TempDir dir;
  write_file_atomically(dir.path() / "cg.100", read_file(kFixtures / "functions_base.cg"));
  write_file_atomically(dir.path() / "cg.101", read_file(kFixtures / "functions_base.cg"));
  write_file_atomically(dir.path() / "unrelated.txt", "not a profile");
  const FunctionProfile sum = read_function_profiles(dir.path());
  EXPECT_EQ(sum.at("shade(Hit const&)").self.ir, 6000u);
  TempDir empty;
  EXPECT_THROW(read_function_profiles(empty.path()), InfraError);
}

TEST(Explanation, RanksFunctionsByIncreaseOfSelfCost) {
  const Explanation e = explain_change(fixture("functions_base.cg"), fixture("functions_head.cg"));
  EXPECT_DOUBLE_EQ(e.base_cycles, 1910 + 690 + 3000 + 100);
  EXPECT_DOUBLE_EQ(e.head_cycles, 1910 + 690 + 10000 + 400 + 50);
  ASSERT_EQ(e.functions.size(), 5u);
  EXPECT_EQ(e.functions[0].name, "shade(Hit const&)");
  EXPECT_DOUBLE_EQ(e.functions[0].delta_cycles(), 7000.0);
  EXPECT_EQ(e.functions[0].base_instructions, 3000u);
  EXPECT_EQ(e.functions[0].head_instructions, 10000u);
  EXPECT_NEAR(share_of_change(e, e.functions[0]), 7000.0 / 7350.0, 1e-12);
  EXPECT_EQ(e.functions[1].name, "sky(Ray const&)");  // new in head
  EXPECT_EQ(e.functions[1].file, "src/sky.cpp");
  EXPECT_EQ(e.functions[4].name, "memcpy");  // cheaper in head: last
  EXPECT_DOUBLE_EQ(e.functions[4].delta_cycles(), -50.0);
  EXPECT_EQ(explain_change(fixture("functions_base.cg"), fixture("functions_head.cg"), 2)
                .functions.size(),
            2u);
}

TEST(Explanation, RoundTripsThroughJsonAndPrintsTheTopFunctions) {
  Explanation e = explain_change(fixture("functions_base.cg"), fixture("functions_head.cg"));
  e.source = ExplainSource::explain_runs;
  e.profiler = "valgrind-3.19.0 cachegrind, self cost";
  e.profile_seconds = 12.5;
  e.native_seconds = 0.25;
  const nlohmann::json json = e;
  EXPECT_EQ(json.at("source"), "explain-runs");
  EXPECT_EQ(json.get<Explanation>(), e);
  const std::vector<std::string> lines = explanation_lines(e, 2);
  ASSERT_EQ(lines.size(), 4u);  // heading, two functions, the profiling cost
  EXPECT_NE(lines[1].find("+7.0k cycles (+95% of the change)"), std::string::npos) << lines[1];
  EXPECT_NE(lines[1].find("shade(Hit const&)"), std::string::npos);
  EXPECT_NE(lines[3].find("12.5 s"), std::string::npos) << lines[3];
  EXPECT_NE(lines[3].find("50x"), std::string::npos) << lines[3];
  nlohmann::json bad = json;
  bad["source"] = "perf";
  EXPECT_THROW(bad.get<Explanation>(), std::invalid_argument);
}

TEST(Explanation, SourceAndCostWordsReadBackAsTheirValues) {
  for (const ExplainSource source : {ExplainSource::explain_runs, ExplainSource::simulated_runs}) {
    EXPECT_EQ(explain_source_named(to_string(source)), source);
  }
  for (const ExplainCost cost : {ExplainCost::instructions, ExplainCost::estimated_cycles}) {
    EXPECT_EQ(explain_cost_named(to_string(cost)), cost);
  }
  EXPECT_EQ(to_string(ExplainSource::explain_runs), "explain-runs");
  EXPECT_EQ(to_string(ExplainCost::estimated_cycles), "estimated-cycles");
  EXPECT_FALSE(explain_source_named("explain_runs").has_value());
  EXPECT_FALSE(explain_cost_named("cycles").has_value());
}

}  // namespace
}  // namespace raygate
