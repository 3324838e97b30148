// A Monte Carlo image check in the results document (images[].monte_carlo): written and read
// back as the same typed comparison, the image kind recorded in settings.images, and on reading
// a comparison whose verdict its own numbers contradict (a "pass" whose interval reaches beyond
// the tolerance) refused with its JSON path. Documents from before both read as they did: a
// Monte Carlo verdict there is a word ("warn") and a sentence in `error`.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "compare/image_check.h"
#include "core/error.h"
#include "results/results.h"
#include "results_fixture.h"

namespace raygate {
namespace {

using nlohmann::json;

NoisyComparison comparison(NoisyVerdict verdict) {
  NoisyComparison c;
  c.verdict = verdict;
  c.tolerance = 0.01;
  c.confidence = 0.9;
  c.width = c.height = 48;
  c.actual_runs = c.expected_runs = 8;
  c.tests = 123;
  c.image = {-0.002, -0.005, 0.001};
  c.channels = {RelativeChange{-0.001, -0.006, 0.004}, RelativeChange{-0.002, -0.005, 0.001},
                RelativeChange{0.0, -0.008, 0.008}};
  c.scales = {{8, 36, 0.03}, {32, 4, 0.008}, {kWholeImage, 1, 0.004}};
  if (verdict == NoisyVerdict::inconclusive) {
    c.image = {-0.0203, -0.032, -0.0086};
    c.samples_factor = 2.5;
    c.runs_needed = 20;
    c.why_inconclusive = "the whole image is shown neither within nor beyond";
  }
  if (verdict == NoisyVerdict::fail) {
    c.image = {-0.03, -0.033, -0.027};
    c.biased_count = 14;
    c.biased.push_back({kWholeImage,
                        {0, 0, 48, 48},
                        1,
                        {-0.03, -0.033, -0.027},
                        0.01,
                        -std::numeric_limits<double>::infinity(),
                        0.0});
  }
  return c;
}

json document_with(const NoisyComparison& noisy) {
  test::DocumentSpec spec;
  spec.sha = test::fake_sha(3);
  spec.scenes = {{"balls", 1.5}};
  ResultsDocument document = test::make_document(spec);
  document.settings.images = ImageKind::monte_carlo;
  document.settings.image_tolerance = 0.01;
  ImageCheck& check = document.scenes[0].images.at(0);
  check.metrics.reset();
  check.noisy = noisy;
  const NoisyVerdict verdict = noisy.verdict;
  check.verdict = verdict == NoisyVerdict::pass   ? ImageVerdict::pass
                  : verdict == NoisyVerdict::fail ? ImageVerdict::fail
                                                  : ImageVerdict::inconclusive;
  return to_json(document);
}

TEST(NoisyImageJson, EveryVerdictRoundTripsTyped) {
  for (const NoisyVerdict verdict :
       {NoisyVerdict::pass, NoisyVerdict::inconclusive, NoisyVerdict::fail}) {
    const json written = document_with(comparison(verdict));
    const ResultsDocument read = results_from_json(json::parse(written.dump()), "mc.json");
    const ImageCheck& check = read.scenes[0].images.at(0);
    ASSERT_TRUE(check.noisy.has_value());
    EXPECT_EQ(*check.noisy, comparison(verdict)) << to_json(read).dump();
    EXPECT_EQ(read.settings.images, ImageKind::monte_carlo);
    EXPECT_EQ(read.settings.image_tolerance, 0.01);
    EXPECT_EQ(to_json(read), written);
  }
  const ImageCheck inconclusive =
      results_from_json(document_with(comparison(NoisyVerdict::inconclusive)), "mc.json")
          .scenes[0]
          .images.at(0);
  EXPECT_EQ(inconclusive.verdict, ImageVerdict::inconclusive);
  EXPECT_NE(check_detail(inconclusive).find("e.g. 20 runs a side"), std::string::npos)
      << check_detail(inconclusive);
}

void expect_refused(const json& j, const std::string& path, const std::string& problem) {
  try {
    results_from_json(j, "forged.json");
    ADD_FAILURE() << path << ": read without an error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
  }
}

TEST(NoisyImageJson, AComparisonItsNumbersContradictIsRefused) {
  const std::string mc = "$.scenes[0].images[0].monte_carlo";
  json j = document_with(comparison(NoisyVerdict::pass));
  j["scenes"][0]["images"][0]["monte_carlo"]["image"]["low"] = -0.02;
  expect_refused(j, mc + ".verdict", "beyond the tolerance");
  j = document_with(comparison(NoisyVerdict::pass));
  j["scenes"][0]["images"][0]["verdict"] = "fail";
  expect_refused(j, "$.scenes[0].images[0].verdict", "but monte_carlo.verdict is \"pass\"");
  j = document_with(comparison(NoisyVerdict::pass));
  j["scenes"][0]["images"][0]["monte_carlo"]["tolerance"] = -1;
  expect_refused(j, mc + ".tolerance", "out of range");
  j = document_with(comparison(NoisyVerdict::inconclusive));
  j["scenes"][0]["images"][0]["monte_carlo"]["image"]["change"] = 0.5;
  expect_refused(j, mc + ".image", "expected low <= change <= high");
  j = document_with(comparison(NoisyVerdict::fail));
  j["scenes"][0]["images"][0]["monte_carlo"]["biased"][0]["channel"] = 3;
  expect_refused(j, mc + ".biased[0].channel", "out of range");
  j = document_with(comparison(NoisyVerdict::fail));
  j["scenes"][0]["images"][0]["monte_carlo"]["verdict"] = "maybe";
  expect_refused(j, mc + ".verdict", "unknown value \"maybe\"");
  j = document_with(comparison(NoisyVerdict::pass));
  j["settings"]["images"] = "painted";
  expect_refused(j, "$.settings.images", "unknown image kind \"painted\"");
}

// A document written before images[].monte_carlo and settings.images.
TEST(NoisyImageJson, OlderDocumentsStillRead) {
  json j = document_with(comparison(NoisyVerdict::inconclusive));
  json& image = j["scenes"][0]["images"][0];
  image.erase("monte_carlo");
  image["verdict"] = "warn";
  image["error"] = "inconclusive (too noisy: the whole image resolves 4.2%, needs 3%)";
  j["settings"].erase("images");
  j["settings"].erase("image_tolerance");
  const ResultsDocument read = results_from_json(j, "old.json");
  const ImageCheck& check = read.scenes[0].images.at(0);
  EXPECT_EQ(check.verdict, ImageVerdict::warn);
  EXPECT_FALSE(check.noisy.has_value());
  EXPECT_EQ(check_detail(check), image["error"].get<std::string>());
  EXPECT_FALSE(read.settings.images.has_value());
}

}  // namespace
}  // namespace raygate
