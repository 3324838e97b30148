// Roles are a type in the results (issue 41): a scene's ratios, the suite scores and the scaling
// fits are keyed by Role in memory and by the role's word only in the JSON. The known words
// round-trip byte for byte; a key that names no role (or names the baseline, which has no ratio
// of its own) is refused as a usage error naming the file and the key's JSON path, whichever map
// it is in.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "core/json_field.h"
#include "results/results.h"
#include "results/typed_fields.h"
#include "results_fixture.h"

namespace raygate {
namespace {

using nlohmann::json;

ResultsDocument document_of(DocumentKind kind) {
  test::DocumentSpec spec;
  spec.sha = test::fake_sha(7);
  spec.kind = kind;
  spec.roles = revision_roles(kind);
  spec.with_change = is_compare(kind);
  spec.scenes = {{"balls", 1.5}, {"gears", 2.0}};
  ResultsDocument d = test::make_document(spec);
  // One family fitted over the tracer, so the scaling part's maps by role are written too.
  ScalingPoint point;
  point.scene_id = "balls";
  point.size = 1;
  point.primitives = 11;
  point.baseline_seconds = 1.0;
  FamilyScaling family;
  family.family = "balls";
  family.series_id = "0123456789abcdef";
  for (const Role role : spec.roles) {
    point.seconds[role] = 1.5;
    point.ratios[role] = 1.5;
    family.roles[role] = RoleScaling{};
  }
  family.points = {point};
  d.scaling = ScalingAnalysis{{family}, 0.1};
  return d;
}

std::vector<std::string> keys_of(const json& object) {
  std::vector<std::string> keys;
  for (const auto& item : object.items()) keys.push_back(item.key());
  return keys;
}

struct Refusal {
  std::string message;
  ExitCode code = ExitCode::pass;
};

Refusal refusal_of(const json& document) {
  try {
    results_from_json(document, "doc.json");
  } catch (const UsageError& e) {
    return {e.what(), e.code()};
  }
  return {"no error", ExitCode::pass};
}

void expect_refused(const json& document, const std::string& where) {
  const Refusal refusal = refusal_of(document);
  EXPECT_EQ(refusal.code, ExitCode::usage) << refusal.message;
  EXPECT_NE(refusal.message.find("doc.json: " + where), std::string::npos) << refusal.message;
}

TEST(RoleKeys, KnownRolesRoundTripUnderTheirWords) {
  for (const DocumentKind kind : {DocumentKind::run, DocumentKind::compare}) {
    const ResultsDocument written = document_of(kind);
    const json j = to_json(written);
    const std::vector<std::string> words = is_compare(kind)
                                               ? std::vector<std::string>{"base", "head"}
                                               : std::vector<std::string>{"tracer"};
    EXPECT_EQ(keys_of(j.at("scenes").at(0).at("ratios")), words);
    EXPECT_EQ(keys_of(j.at("scores")), words);
    const json& family = j.at("scaling").at("families").at(0);
    EXPECT_EQ(keys_of(family.at("roles")), words);
    EXPECT_EQ(keys_of(family.at("points").at(0).at("seconds")), words);

    const ResultsDocument back = results_from_json(j, "doc.json");
    for (const Role role : revision_roles(kind)) {
      const SceneResult& scene = back.scenes.at(1);
      ASSERT_NE(scene.ratio(role), nullptr) << to_string(role);
      EXPECT_DOUBLE_EQ(scene.ratio(role)->ratio, written.scenes.at(1).ratio(role)->ratio);
      EXPECT_EQ(back.scores.at(role).scenes, 2u);
      EXPECT_DOUBLE_EQ(back.scores.at(role).score, written.scores.at(role).score);
      EXPECT_EQ(back.scaling->families.at(0).points.at(0).ratios.at(role), 1.5);
      EXPECT_EQ(back.scaling->families.at(0).roles.count(role), 1u);
    }
    EXPECT_EQ(back.scenes.at(0).ratios.size(), words.size());
    EXPECT_EQ(to_json(back).dump(), j.dump()) << "written again, byte for byte";
  }
}

TEST(RoleKeys, AnUnknownRoleInRatiosIsRefusedAtItsPath) {
  json j = to_json(document_of(DocumentKind::run));
  j["scenes"][1]["ratios"]["mallory"] = j["scenes"][1]["ratios"]["tracer"];
  expect_refused(j, "$.scenes[1].ratios.mallory: unknown role \"mallory\"");

  json compare = to_json(document_of(DocumentKind::compare));
  compare["scenes"][0]["ratios"]["Head"] = compare["scenes"][0]["ratios"]["head"];
  compare["scenes"][0]["ratios"].erase("head");
  expect_refused(compare, "$.scenes[0].ratios.Head: unknown role \"Head\"");
}

// The baseline is a role of runs, not of ratios: each ratio is a revision's against it.
TEST(RoleKeys, TheBaselineHasNoRatioOrScore) {
  json j = to_json(document_of(DocumentKind::run));
  j["scenes"][0]["ratios"]["baseline"] = j["scenes"][0]["ratios"]["tracer"];
  expect_refused(j, "$.scenes[0].ratios.baseline: unknown role \"baseline\"");
  json scores = to_json(document_of(DocumentKind::run));
  scores["scores"]["baseline"] = scores["scores"]["tracer"];
  expect_refused(scores, "$.scores.baseline: unknown role \"baseline\"");
}

TEST(RoleKeys, AnUnknownRoleInScoresIsRefusedAtItsPath) {
  json j = to_json(document_of(DocumentKind::compare));
  j["scores"]["mallory"] = j["scores"]["head"];
  expect_refused(j, "$.scores.mallory: unknown role \"mallory\"");
}

TEST(RoleKeys, AnUnknownRoleInTheScalingFitsIsRefusedAtItsPath) {
  json j = to_json(document_of(DocumentKind::run));
  json& family = j["scaling"]["families"][0];
  family["roles"]["trace"] = family["roles"]["tracer"];
  expect_refused(j, "$.scaling.families[0].roles.trace: unknown role \"trace\"");

  json points = to_json(document_of(DocumentKind::run));
  points["scaling"]["families"][0]["points"][0]["seconds"]["ghost"] = 1.0;
  expect_refused(points, "$.scaling.families[0].points[0].seconds.ghost: unknown role \"ghost\"");
}

// The reader does not rely on the check before it: a word that names no role is refused where
// the map is read.
TEST(RoleKeys, TheMapReaderRefusesAWordThatNamesNoRole) {
  const json known = {{"base", 1.0}, {"head", 2.0}};
  const std::map<Role, double> read =
      typed_fields::by_role(JsonField(known, "$.m"), typed_fields::number_or_nan);
  EXPECT_EQ(read, (std::map<Role, double>{{Role::base, 1.0}, {Role::head, 2.0}}));
  EXPECT_EQ(typed_fields::role_object(read, [](double x) { return json(x); }), known);

  const json unknown = {{"head", 1.0}, {"HEAD", 2.0}};
  try {
    typed_fields::by_role(JsonField(unknown, "$.m"), typed_fields::number_or_nan);
    ADD_FAILURE() << "HEAD read as a role";
  } catch (const FieldError& e) {
    EXPECT_EQ(e.path(), "$.m.HEAD");
    EXPECT_NE(std::string(e.what()).find("unknown role \"HEAD\""), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raygate
