// Placeholder expansion: per element, several per element, escapes, single pass, and no shell:
// `;`, `$(...)` and quotes in templates or values reach the program as those characters.
#include <gtest/gtest.h>

#include <stdexcept>

#include "adapter/placeholders.h"
#include "core/fs.h"
#include "core/process.h"

namespace raygate {
namespace {

Placeholders run_values() {
  Placeholders p;
  p.build = "/b";
  p.scene = "/s/balls.nff";
  p.scene_stem = "balls";
  p.image = "/w/out.png";
  p.workdir = "/w";
  p.threads = "4";
  p.width = "160";
  p.height = "120";
  return p;
}

TEST(Placeholders, ExpandsEachElement) {
  const std::vector<std::string> argv{"{build}/tracer", "{scene}", "-o", "{image}"};
  EXPECT_EQ(expand(argv, run_values()),
            (std::vector<std::string>{"/b/tracer", "/s/balls.nff", "-o", "/w/out.png"}));
}

TEST(Placeholders, SeveralInOneElement) {
  EXPECT_EQ(expand("--out={workdir}/{scene_stem}-{threads}t.ppm", run_values()),
            "--out=/w/balls-4t.ppm");
  EXPECT_EQ(expand("+I{scene}+O{image}", run_values()), "+I/s/balls.nff+O/w/out.png");
}

TEST(Placeholders, ImageSizeForTracersThatTakeItOnTheCommandLine) {
  // POV-Ray reads the size only from its options (adapters/povray.json).
  EXPECT_EQ(expand(std::vector<std::string>{"+W{width}", "+H{height}", "--size={width}x{height}"},
                   run_values()),
            (std::vector<std::string>{"+W160", "+H120", "--size=160x120"}));
  EXPECT_EQ(template_error("{width}", TemplateField::build),
            "placeholder '{width}' is not available in build steps (available: {src}, "
            "{repo_root}, {build}, {jobs}, {raygate_source})");
}

TEST(Placeholders, DoubledBracesAreLiteral) {
  EXPECT_EQ(expand("{{scene}}", run_values()), "{scene}");
  EXPECT_EQ(expand("{{{scene}}}", run_values()), "{/s/balls.nff}");
  EXPECT_EQ(expand("json={{\"n\": {threads}}}", run_values()), "json={\"n\": 4}");
  EXPECT_FALSE(uses_placeholder("{{scene}}", "scene"));
  EXPECT_TRUE(uses_placeholder("x{scene}", "scene"));
}

TEST(Placeholders, ValuesAreNotExpandedAgain) {
  Placeholders p = run_values();
  p.scene = "/tmp/{image}";  // a path that happens to hold braces
  EXPECT_EQ(expand("{scene}", p), "/tmp/{image}");
}

TEST(Placeholders, ShellSyntaxStaysLiteral) {
  Placeholders p = run_values();
  p.scene = "/r/feature;rm -rf ~/$(whoami)`id`";
  EXPECT_EQ(
      expand(std::vector<std::string>{"t", "a;b", "$(echo hi)", "{scene}"}, p),
      (std::vector<std::string>{"t", "a;b", "$(echo hi)", "/r/feature;rm -rf ~/$(whoami)`id`"}));
}

TEST(Placeholders, ShellSyntaxReachesTheProgramVerbatim) {
  TempDir dir;
  Placeholders p = run_values();
  p.scene = "x; echo injected $(echo sub) `echo tick`";
  ProcessSpec spec;
  spec.argv = expand(std::vector<std::string>{"printf", "%s|", "{scene}", "a;b"}, p);
  spec.stdout_path = dir.path() / "out.txt";
  ASSERT_TRUE(run_process(spec).succeeded());
  EXPECT_EQ(read_file(spec.stdout_path), "x; echo injected $(echo sub) `echo tick`|a;b|");
}

TEST(Placeholders, UnsetOrMalformedIsAProgrammingError) {
  Placeholders build_only;
  build_only.build = "/b";
  EXPECT_THROW(expand("{scene}", build_only), std::logic_error);
  EXPECT_THROW(expand("{nope}", run_values()), std::logic_error);
  EXPECT_THROW(expand("{scene", run_values()), std::logic_error);
  EXPECT_THROW(expand("scene}", run_values()), std::logic_error);
}

TEST(Placeholders, WhereEachIsAllowed) {
  for (const char* name : {"src", "repo_root", "build", "jobs", "raygate_source"}) {
    EXPECT_EQ(template_error(std::string("{") + name + "}", TemplateField::build), std::nullopt)
        << name;
  }
  for (const char* name :
       {"threads", "scene", "image", "workdir", "scene_stem", "width", "height"}) {
    EXPECT_NE(template_error(std::string("{") + name + "}", TemplateField::build), std::nullopt)
        << name;
  }
  for (const char* name : {"src", "repo_root", "build", "threads", "scene", "image", "workdir",
                           "raygate_source", "scene_stem", "width", "height", "seed"}) {
    EXPECT_EQ(template_error(std::string("{") + name + "}", TemplateField::run), std::nullopt)
        << name;
  }
  EXPECT_NE(template_error("{jobs}", TemplateField::run), std::nullopt);
  EXPECT_NE(template_error("{seed}", TemplateField::build), std::nullopt);
  EXPECT_EQ(placeholder_names().size(), 13u);
}

TEST(Placeholders, BraceErrors) {
  EXPECT_EQ(template_error("a}b", TemplateField::run),
            "unmatched '}' (write '}}' for a literal brace)");
  EXPECT_EQ(template_error("{}", TemplateField::run),
            "unknown placeholder '{}' (known: {src}, {repo_root}, {build}, {jobs}, {threads}, "
            "{scene}, {image}, {workdir}, {raygate_source}, {scene_stem}, {width}, "
            "{height}, {seed})");
  EXPECT_EQ(template_error("{Scene}", TemplateField::run),
            "unknown placeholder '{Scene}' (did you mean '{scene}'?)");
}

}  // namespace
}  // namespace raygate
