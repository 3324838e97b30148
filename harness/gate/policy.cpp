#include "gate/policy.h"

#include <fmt/core.h>

#include "core/json_field.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/json_reader.h"

namespace raygate {

namespace {

const std::vector<std::string> kSceneKeys = {"max_slowdown", "max_memory_increase", "significance",
                                             "image",        "image_tolerance",     "reason"};
const std::vector<std::string> kImageKeys = {"fail", "failpercent", "hardfail", "warn"};

double fraction(const JsonField& field, double low, double high) {
  const double value = field.as_number();
  if (!(value >= low && value <= high)) {
    field.fail(fmt::format("must be between {} and {}, found {}", low, high, value));
  }
  return value;
}

void read_image(const JsonField& field, ImageThresholds& image) {
  field.expect_object(kImageKeys);
  if (field.has("fail")) image.fail_threshold = fraction(field.member("fail"), 0.0, 1e30);
  if (field.has("failpercent"))
    image.fail_percent = fraction(field.member("failpercent"), 0.0, 100.0);
  if (field.has("hardfail")) image.hard_fail = fraction(field.member("hardfail"), 0.0, 1e30);
  if (field.has("warn")) image.warn_threshold = fraction(field.member("warn"), 0.0, 1e30);
}

// Reads the keys a scene override and the defaults share into `policy`.
void read_scene_keys(const JsonField& field, ScenePolicy& policy) {
  if (field.has("max_slowdown"))
    policy.max_slowdown = fraction(field.member("max_slowdown"), 0.0, 10.0);
  if (field.has("max_memory_increase")) {
    policy.max_memory_increase = fraction(field.member("max_memory_increase"), 0.0, 100.0);
  }
  if (field.has("significance"))
    policy.significance = fraction(field.member("significance"), 0.0001, 0.5);
  if (field.has("image")) read_image(field.member("image"), policy.image);
  if (field.has("image_tolerance")) {
    policy.image_tolerance = fraction(field.member("image_tolerance"), 0.0001, 1.0);
  }
}

}  // namespace

const ScenePolicy& GatePolicy::for_scene(const std::string& id) const {
  const auto found = scenes.find(id);
  return found == scenes.end() ? defaults : found->second;
}

GatePolicy parse_policy(std::string_view text, const std::string& origin) {
  // Duplicate keys and out-of-range numbers refused with where they are (core/json_reader.h).
  const nlohmann::json document = parse_json_input(text, origin);
  GatePolicy policy;
  try {
    const JsonField root(document, "$");
    root.expect_object({"max_slowdown", "max_memory_increase", "significance",
                        "family_significance", "image", "image_tolerance", "fail_on_inconclusive",
                        "max_exponent_increase", "scenes"});
    read_scene_keys(root, policy.defaults);
    if (root.has("family_significance")) {
      policy.family_significance = fraction(root.member("family_significance"), 0.0001, 0.5);
    }
    if (root.has("fail_on_inconclusive")) {
      policy.fail_on_inconclusive = root.member("fail_on_inconclusive").as_bool();
    }
    if (root.has("max_exponent_increase")) {
      policy.max_exponent_increase = fraction(root.member("max_exponent_increase"), 0.0, 10.0);
    }
    if (root.has("scenes")) {
      const JsonField scenes = root.member("scenes");
      scenes.expect_object(scenes.keys());
      for (const std::string& id : scenes.keys()) {
        const JsonField entry = scenes.member(id);
        entry.expect_object(kSceneKeys);
        ScenePolicy scene = policy.defaults;
        read_scene_keys(entry, scene);
        scene.reason = entry.member("reason").as_string();
        if (scene.reason.empty()) entry.member("reason").fail("must say why this scene differs");
        policy.scenes[id] = scene;
      }
    }
  } catch (const FieldError& e) {
    throw UsageError(fmt::format("{}: {}: {}", origin, e.path(), e.what()));
  }
  return policy;
}

GatePolicy load_policy(const std::filesystem::path& path) {
  std::string text;
  try {
    text = read_json_text(path);
  } catch (const UsageError& e) {  // "/x: cannot open" said nothing of which file it was
    throw UsageError(std::string("the policy file (--policy) ") + e.what());
  }
  GatePolicy policy = parse_policy(text, path.string());
  policy.file = path;
  return policy;
}

GatePolicy recorded_policy(const MeasurementSettings& settings, std::string& note) {
  const std::string file = settings.policy_file.value_or("");
  if (!file.empty() && std::filesystem::is_regular_file(file)) {
    note = "the policy it was measured under, " + file;
    return load_policy(file);
  }
  GatePolicy policy;
  policy.defaults.max_slowdown = settings.max_slowdown.value_or(policy.defaults.max_slowdown);
  policy.defaults.significance = settings.significance.value_or(policy.defaults.significance);
  policy.defaults.max_memory_increase =
      settings.max_memory_increase.value_or(policy.defaults.max_memory_increase);
  policy.defaults.image_tolerance =
      settings.image_tolerance.value_or(policy.defaults.image_tolerance);
  policy.max_exponent_increase =
      settings.max_exponent_increase.value_or(policy.max_exponent_increase);
  policy.family_significance = settings.family_significance.value_or(policy.family_significance);
  note = fmt::format("the limits it was measured under (max_slowdown {}, significance {}){}",
                     policy.defaults.max_slowdown, policy.defaults.significance,
                     file.empty() ? ""
                                  : "; its policy file " + file +
                                        " is not here, so per-scene overrides are not applied");
  return policy;
}

}  // namespace raygate
