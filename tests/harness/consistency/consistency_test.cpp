// Consistency of ratios across machines on hand-made documents (results_fixture): r² against
// values computed with bench/paper-experiment's Python formula, per-scene deviation and CV,
// unstable scenes (deviation and disjoint CIs), missing scenes, and the refusals.
#include "consistency/consistency.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "consistency/consistency_report.h"
#include "core/error.h"
#include "results_fixture.h"

namespace raygate::test {
namespace {

using ::testing::HasSubstr;

DocumentSpec machine(const std::string& host, const std::vector<double>& ratios) {
  DocumentSpec spec;
  spec.sha = fake_sha(1);
  spec.hostname = host;
  spec.cpu_model = host == "straylight" ? "Intel Core i5 750" : "Intel Core2 Duo";
  const char* ids[] = {"balls", "gears", "mount", "rings", "teapot"};
  for (std::size_t i = 0; i < ratios.size(); ++i) spec.scenes.push_back({ids[i], ratios[i], 0.01});
  return spec;
}

DocumentRatios ratios_of(const DocumentSpec& spec, std::size_t index) {
  return document_ratios(make_document(spec), spec.hostname + ".json", document_label(index));
}

ConsistencyResult analyse(const std::vector<DocumentSpec>& specs, ConsistencyOptions options = {}) {
  std::vector<DocumentRatios> documents;
  for (std::size_t i = 0; i < specs.size(); ++i) documents.push_back(ratios_of(specs[i], i));
  return analyse_consistency(std::move(documents), options);
}

const std::vector<double> kA{0.5, 0.8, 1.2, 1.5, 0.9};
const std::vector<double> kB{0.52, 0.79, 1.25, 1.45, 0.95};

TEST(Consistency, RSquaredMatchesThePaperExperimentFormula) {
  EXPECT_NEAR(r_squared({1, 2, 3, 4}, {1.1, 1.9, 3.2, 3.9}), 0.9867855270057682, 1e-12);
  EXPECT_NEAR(r_squared(kA, kB), 0.9888153459582032, 1e-12);
  EXPECT_DOUBLE_EQ(r_squared({1, 2, 3}, {2, 4, 6}), 1.0);
  EXPECT_TRUE(std::isnan(r_squared({1, 1, 1}, {1, 2, 3})));  // no variance: undefined
  EXPECT_TRUE(std::isnan(r_squared({1, 2}, {1, 2, 3})));
}

TEST(Consistency, CloseRatiosOnTwoMachinesAreMachineIndependent) {
  const ConsistencyResult r =
      analyse({machine("straylight", kA), machine("neolith", kB)}, {0.9, 0.1, false});
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_NEAR(r.pairs[0].r2, 0.9888153459582032, 1e-12);
  EXPECT_NEAR(r.overall_r2, r.pairs[0].r2, 1e-12);  // two documents: overall is the pair
  EXPECT_EQ(r.pairs[0].scenes, 5u);
  EXPECT_TRUE(r.pairs[0].passes);
  EXPECT_EQ(r.scenes.size(), 5u);
  // balls: 0.5 and 0.52 -> mean 0.51, deviation 0.01/0.51 for both, CV (population) the same.
  EXPECT_EQ(r.scenes[0].id, "balls");
  EXPECT_NEAR(r.scenes[0].mean_ratio, 0.51, 1e-12);
  EXPECT_NEAR(r.scenes[0].max_deviation, 0.01 / 0.51, 1e-12);
  EXPECT_NEAR(r.scenes[0].mean_deviation, 0.01 / 0.51, 1e-12);
  EXPECT_NEAR(r.scenes[0].cv, 0.01 / 0.51, 1e-12);
  // rings: 1.5 and 1.45, CIs of ±1% do not overlap ([1.485, 1.515] and [1.4355, 1.4645]).
  EXPECT_FALSE(r.scenes[3].intervals_overlap);
  EXPECT_TRUE(r.scenes[3].unstable);
  EXPECT_THAT(r.scenes[3].reasons.at(0), HasSubstr("CIs do not overlap"));
  EXPECT_FALSE(r.machine_independent());
  EXPECT_EQ(r.exit_code(), 1);
}

TEST(Consistency, WideIntervalsOverlapAndPass) {
  DocumentSpec a = machine("straylight", kA), b = machine("neolith", kB);
  for (auto* spec : {&a, &b}) {
    for (SceneSpec& s : spec->scenes) s.half_width = 0.05;
  }
  const ConsistencyResult r = analyse({a, b});
  EXPECT_TRUE(r.unstable_scenes().empty());
  EXPECT_TRUE(r.machine_independent());
  EXPECT_EQ(r.exit_code(), 0);
}

TEST(Consistency, ADeviatingSceneIsUnstableWithItsNumbers) {
  DocumentSpec a = machine("straylight", kA), b = machine("neolith", kA);
  for (auto* spec : {&a, &b}) {
    for (SceneSpec& s : spec->scenes) s.half_width = 0.5;  // intervals overlap: deviation only
  }
  b.scenes[2].ratio = 1.2 * 1.3;  // mount: 1.2 vs 1.56, mean 1.38, 13.04% each way
  ConsistencyOptions options;
  options.min_r2 = 0.8;  // r² is 0.8906 here: only the deviation decides
  const ConsistencyResult r = analyse({a, b}, options);
  const auto unstable = r.unstable_scenes();
  ASSERT_EQ(unstable.size(), 1u);
  EXPECT_EQ(unstable[0]->id, "mount");
  EXPECT_NEAR(unstable[0]->max_deviation, 0.18 / 1.38, 1e-12);
  EXPECT_THAT(unstable[0]->reasons.at(0), HasSubstr("13.0% from the mean 1.38 (limit 10.0%)"));
  EXPECT_EQ(r.exit_code(), 1);
  ConsistencyOptions loose = options;
  loose.max_deviation = 0.2;
  EXPECT_EQ(analyse({a, b}, loose).exit_code(), 0);
}

TEST(Consistency, UnrelatedRatiosFailTheR2) {
  DocumentSpec a = machine("straylight", kA);
  DocumentSpec b = machine("neolith", {1.5, 0.5, 0.9, 0.8, 1.2});
  for (auto* spec : {&a, &b}) {
    for (SceneSpec& s : spec->scenes) s.half_width = 2.0;
  }
  ConsistencyOptions options;
  options.max_deviation = 10.0;  // only the r² decides
  const ConsistencyResult r = analyse({a, b}, options);
  EXPECT_LT(r.pairs[0].r2, 0.5);
  EXPECT_FALSE(r.pairs[0].passes);
  EXPECT_EQ(r.exit_code(), 1);
  EXPECT_THAT(consistency_table(r), HasSubstr("NOT machine-independent"));
}

TEST(Consistency, ThreeDocumentsGiveThreePairsAndOverall) {
  const ConsistencyResult r =
      analyse({machine("straylight", kA), machine("neolith", kB), machine("monolith", kA)});
  ASSERT_EQ(r.pairs.size(), 3u);
  EXPECT_EQ(r.pairs[2].a, 1u);
  EXPECT_EQ(r.pairs[2].b, 2u);
  EXPECT_DOUBLE_EQ(r.pairs[1].r2, 1.0);  // A vs C: identical
  EXPECT_NEAR(r.min_pair_r2, 0.9888153459582032, 1e-12);
  EXPECT_GT(r.overall_r2, r.min_pair_r2);
  EXPECT_LT(r.overall_r2, 1.0);
}

TEST(Consistency, MissingSceneIsReportedAndExcluded) {
  DocumentSpec b = machine("neolith", kB);
  b.scenes.erase(b.scenes.begin() + 1);          // no gears
  b.scenes.back().status = SceneStatus::failed;  // teapot failed: not measured either
  const ConsistencyResult r = analyse({machine("straylight", kA), b});
  ASSERT_EQ(r.missing.size(), 2u);
  EXPECT_EQ(r.missing[0].id, "gears");
  EXPECT_EQ(r.missing[0].missing_from, std::vector<std::size_t>{1});
  EXPECT_EQ(r.missing[1].id, "teapot");
  EXPECT_EQ(r.scenes.size(), 3u);
  EXPECT_EQ(r.pairs[0].scenes, 3u);
  EXPECT_THAT(consistency_table(r), HasSubstr("missing: gears not measured in B (excluded)"));
}

TEST(Consistency, CompareDocumentsUseTheHeadRatio) {
  DocumentSpec spec = machine("neolith", kA);
  spec.kind = DocumentKind::compare;
  spec.roles = {Role::base, Role::head};
  ResultsDocument document = make_document(spec);
  for (SceneResult& scene : document.scenes) scene.ratios[Role::base].ratio = 9.0;
  const DocumentRatios d = document_ratios(document, "cmp.json", "A");
  EXPECT_EQ(d.role, Role::head);
  EXPECT_DOUBLE_EQ(d.scenes.at("balls").ratio, 0.5);
  document.revisions.pop_back();  // no head revision
  EXPECT_THROW(document_ratios(document, "cmp.json", "A"), UsageError);
}

TEST(Consistency, RefusesDifferentBaselinesUnlessAllowed) {
  DocumentSpec b = machine("neolith", kB);
  b.baseline_sha256 = std::string(64, 'c');
  try {
    analyse({machine("straylight", kA), b});
    FAIL() << "mixed baselines accepted";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("different raygate-baseline sources"));
    EXPECT_THAT(e.what(), HasSubstr("cccccccccccc"));
    EXPECT_THAT(e.what(), HasSubstr("--allow-mixed"));
  }
  ConsistencyOptions allow;
  allow.allow_mixed = true;
  const ConsistencyResult r = analyse({machine("straylight", kA), b}, allow);
  ASSERT_EQ(r.mixed.size(), 1u);
  EXPECT_THAT(consistency_table(r), HasSubstr("mixed (--allow-mixed)"));
}

TEST(Consistency, RefusesDifferentTracerRevisions) {
  DocumentSpec b = machine("neolith", kB);
  b.sha = fake_sha(2);
  try {
    analyse({machine("straylight", kA), b});
    FAIL() << "mixed revisions accepted";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("different tracer revisions"));
  }
}

TEST(Consistency, RefusesTooFewDocumentsOrScenes) {
  EXPECT_THROW(analyse({machine("straylight", kA)}), UsageError);
  EXPECT_THROW(analyse({machine("straylight", {1.0, 2.0}), machine("neolith", {1.0, 2.0})}),
               UsageError);
  ConsistencyOptions bad;
  bad.min_r2 = 1.5;
  EXPECT_THROW(analyse({machine("straylight", kA), machine("neolith", kB)}, bad), UsageError);
}

TEST(Consistency, RatiosThatDoNotVaryAcrossScenesCannotBeFittedAndAreRefused) {
  const std::vector<double> flat{0.5, 0.5, 0.5};
  try {
    analyse({machine("straylight", flat), machine("neolith", flat)});
    FAIL() << "identical flat documents accepted";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("A (straylight.json) has the same ratio, 0.5000, on all 3"));
  }
  EXPECT_THROW(analyse({machine("straylight", {0.5, 0.8, 1.2}), machine("neolith", flat)}),
               UsageError);
}

TEST(Consistency, ReportsNameMachinesAndCarryTheNumbers) {
  const ConsistencyResult r = analyse({machine("straylight", kA), machine("neolith", kB)});
  const std::string table = consistency_table(r);
  EXPECT_THAT(table, HasSubstr("straylight  Intel Core i5 750"));
  EXPECT_THAT(table, HasSubstr("neolith  Intel Core2 Duo"));
  EXPECT_THAT(table, HasSubstr("raygate-baseline 0.1.0 (bbbbbbbbbbbb)"));
  EXPECT_THAT(table, HasSubstr("A vs B"));
  EXPECT_THAT(table, HasSubstr("r² 0.9888"));
  const nlohmann::json json = consistency_json(r);
  EXPECT_NEAR(json["pairs"][0]["r2"].get<double>(), 0.9888153459582032, 1e-12);
  EXPECT_EQ(json["documents"][1]["hostname"], "neolith");
  // ±1% CIs: balls, mount, rings and teapot differ by more than their intervals allow.
  EXPECT_EQ(json["unstable"], nlohmann::json::array({"balls", "mount", "rings", "teapot"}));
  EXPECT_EQ(json["machine_independent"], false);
  const std::string markdown = consistency_markdown(r);
  EXPECT_THAT(markdown, HasSubstr("| A vs B | 5 | 0.9888 |"));
  EXPECT_THAT(markdown, HasSubstr("| rings **unstable** |"));
}

}  // namespace
}  // namespace raygate::test
