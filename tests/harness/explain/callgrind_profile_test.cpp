// Self and inclusive cost from callgrind files (explain/callgrind_profile.h): a hand-written file
// whose sums are worked out here (compressed names, a call's inclusive cost line, an inlined
// file's lines, a direct recursion, "*" and "+N" positions), two position columns, malformed
// files refused with their line, a real callgrind run whose self costs add up to its totals, and
// an explanation by instructions that ranks by self and carries the inclusive change.
#include "explain/callgrind_profile.h"

#include <gtest/gtest.h>

#include <sstream>

#include "core/error.h"
#include "core/fs.h"
#include "core/process.h"
#include "explain/explanation.h"

namespace raygate {
namespace {

const std::filesystem::path kFixtures =
    std::filesystem::path(RAYGATE_SOURCE_DIR) / "tests" / "fixtures" / "callgrind";

FunctionProfile fixture(const std::string& name) {
  return parse_callgrind_profile(read_file(kFixtures / name), name);
}

TEST(CallgrindProfile, SelfAndInclusiveCostPerFunctionWithCompressedNames) {
  const FunctionProfile p = fixture("calls.out");
  ASSERT_EQ(p.size(), 3u);
  const FunctionCost& main_cost = p.at("main");
  EXPECT_EQ(main_cost.self.ir, 15u);         // 10 + 5; the call line is not its own cost
  EXPECT_EQ(main_cost.inclusive.ir, 1335u);  // + its call of trace (1320)
  const FunctionCost& trace = p.at("trace(Ray const&)");  // "(2)" named once, demangled
  EXPECT_EQ(trace.file, "src/trace.cpp");
  EXPECT_EQ(trace.self.ir, 120u);        // 100, and 20 from the inlined header's line
  EXPECT_EQ(trace.inclusive.ir, 1320u);  // + intersect (1200); the recursive call left out
  const FunctionCost& intersect = p.at("intersect(Ray const&)");
  EXPECT_EQ(intersect.self.ir, 1200u);
  EXPECT_EQ(intersect.inclusive.ir, 1200u);
  EXPECT_TRUE(intersect.inclusive_known);
}

TEST(CallgrindProfile, ReadsFilesWithTwoPositionColumns) {
  const FunctionProfile p = fixture("two_positions.out");
  EXPECT_EQ(p.at("f").self.ir, 10u);
  EXPECT_EQ(p.at("f").self.dr, 2u);
  EXPECT_EQ(p.at("f").inclusive.ir, 21u);
  EXPECT_EQ(p.at("g").inclusive.ir, 11u);
}

TEST(CallgrindProfile, RefusesMalformedFilesWithTheirLine) {
  const std::string events = "events: Ir\n";
  EXPECT_THROW(parse_callgrind_profile("fn=main\n1 2\n", "c.out"), InfraError);  // no events
  try {
    parse_callgrind_profile(events + "fn=(1) f\ncfn=(7)\ncalls=1 2\n3 4\n", "c.out");
    FAIL() << "an undefined name id was accepted";
  } catch (const InfraError& e) {
    EXPECT_NE(std::string(e.what()).find("c.out:3: name id (7) used before it is defined"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parse_callgrind_profile(events + "fl=a.c\n3 4\n", "c.out"), InfraError);
  EXPECT_THROW(parse_callgrind_profile(events + "fn=f\n1 2 3\n", "c.out"), InfraError);
  EXPECT_THROW(parse_callgrind_profile(events + "fn=f\n1 2x\n", "c.out"), InfraError);
}

// The "totals:" line of a callgrind file.
std::uint64_t totals_of(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("totals:")) return std::stoull(line.substr(7));
  }
  return 0;
}

// Real output of Debian's valgrind, a shell that runs a child: every process a file, the self
// costs of each file add up to its totals, and no function costs more by itself than with its
// callees. Fails (not skips) without valgrind, as the other explain tests do.
TEST(CallgrindProfile, ARealRunsSelfCostsAddUpToItsTotals) {
  TempDir dir;
  ProcessSpec spec;
  spec.argv = {"/bin/sh", "-c", "/bin/true; /bin/true"};
  spec.timeout = std::chrono::seconds(120);
  const ProcessResult result = run_process(under_callgrind(spec, Cachegrind{}, dir.path()));
  ASSERT_TRUE(result.succeeded()) << result.describe();
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    const std::string text = read_file(entry.path());
    const FunctionProfile p = parse_callgrind_profile(text, entry.path().string());
    std::uint64_t self = 0;
    for (const auto& [name, cost] : p) {
      self += cost.self.ir;
      EXPECT_GE(cost.inclusive.ir, cost.self.ir) << name;
    }
    EXPECT_EQ(self, totals_of(text)) << entry.path();
    ++files;
  }
  EXPECT_GE(files, 2u);  // the shell and its children (dash may exec the last one itself)
  const FunctionProfile sum = read_callgrind_profiles(dir.path());
  EXPECT_FALSE(sum.empty());
}

TEST(CallgrindProfile, AnExplanationByInstructionsRanksBySelfAndKeepsInclusive) {
  const FunctionProfile base = fixture("calls.out");
  FunctionProfile head = base;
  head.at("intersect(Ray const&)").self.ir += 800;  // the slowed function
  head.at("intersect(Ray const&)").inclusive.ir += 800;
  head.at("trace(Ray const&)").inclusive.ir += 800;  // its caller, by inclusive cost only
  head.at("main").inclusive.ir += 800;
  const Explanation e = explain_change(base, head, 10, ExplainCost::instructions);
  EXPECT_EQ(e.cost, ExplainCost::instructions);
  EXPECT_TRUE(e.inclusive);
  EXPECT_EQ(e.base_instructions, 1335u);
  EXPECT_EQ(e.head_instructions, 2135u);
  ASSERT_EQ(e.functions.size(), 3u);
  EXPECT_EQ(e.functions[0].name, "intersect(Ray const&)");
  EXPECT_DOUBLE_EQ(e.delta_of(e.functions[0]), 800.0);
  EXPECT_DOUBLE_EQ(share_of_change(e, e.functions[0]), 1.0);
  EXPECT_EQ(e.functions[0].base_cycles, 0.0);  // no cache simulation: no cycles claimed
  const auto trace =
      std::find_if(e.functions.begin(), e.functions.end(),
                   [](const FunctionChange& f) { return f.name.starts_with("trace"); });
  ASSERT_NE(trace, e.functions.end());
  EXPECT_DOUBLE_EQ(trace->delta_instructions(), 0.0);
  EXPECT_DOUBLE_EQ(trace->delta_inclusive_instructions(), 800.0);
  const nlohmann::json json = e;
  EXPECT_EQ(json.at("cost"), "instructions");
  EXPECT_EQ(json.get<Explanation>(), e);
  const std::vector<std::string> lines = explanation_lines(e, 1);
  EXPECT_NE(lines[0].find("instructions 1.3k -> 2.1k"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("+800 instructions (+100% of the change), inclusive 1.2k -> 2.0k"),
            std::string::npos)
      << lines[1];
}

TEST(CallgrindProfile, ADocumentFromBeforeReadsAsCyclesWithoutInclusive) {
  nlohmann::json old = {{"source", "simulated-runs"},
                        {"profiler", "valgrind-3.19.0 cachegrind"},
                        {"base_cycles", 100.0},
                        {"head_cycles", 150.0},
                        {"profile_seconds", 0.0},
                        {"native_seconds", 0.0},
                        {"functions", nlohmann::json::array({{{"name", "f"},
                                                              {"file", "f.c"},
                                                              {"base_cycles", 100.0},
                                                              {"head_cycles", 150.0},
                                                              {"base_instructions", 90},
                                                              {"head_instructions", 140}}})}};
  const Explanation e = old.get<Explanation>();
  EXPECT_EQ(e.cost, ExplainCost::estimated_cycles);
  EXPECT_FALSE(e.inclusive);
  EXPECT_DOUBLE_EQ(share_of_change(e, e.functions[0]), 1.0);
  EXPECT_EQ(e.functions[0].base_inclusive_instructions, 0u);
}

}  // namespace
}  // namespace raygate
