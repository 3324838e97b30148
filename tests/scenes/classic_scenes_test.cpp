// The seven classic SPD generators (balls, gears, mount, rings, teapot, tetra, tree) against
// spd-spec.md §6: Table A (counts and bytes: equal bytes is the bit-exactness proof short of a
// hash), Table B (bounding box), Table C (background and view lines) and Table D (distinct `f`
// lines), at sizes 1, 2, 3 and the default, plus teapot 12. The generators are called
// directly, not through the registry, so this test does not need the other six scenes.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "generators/generators.h"
#include "lib/nff_writer.h"
#include "nff_summary.h"

namespace raygate::test {
namespace {

using Generator = void (*)(int, scenes::NffWriter&);

Generator generator_for(std::string_view scene) {
  static const std::map<std::string_view, Generator> kGenerators{
      {"balls", scenes::generate_balls},   {"gears", scenes::generate_gears},
      {"mount", scenes::generate_mount},   {"rings", scenes::generate_rings},
      {"teapot", scenes::generate_teapot}, {"tetra", scenes::generate_tetra},
      {"tree", scenes::generate_tree}};
  return kGenerators.at(scene);
}

std::string generate(std::string_view scene, int size) {
  std::ostringstream text;
  scenes::NffWriter writer(text);
  generator_for(scene)(size, writer);
  return text.str();
}

// Each (scene, size) is generated once and shared by the table checks.
const std::string& generated(std::string_view scene, int size) {
  static std::map<std::pair<std::string, int>, std::string> cache;
  const auto key = std::make_pair(std::string(scene), size);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, generate(scene, size)).first;
  return it->second;
}

// One row of Tables A and B.
struct Row {
  const char* scene;
  int size;
  long lines;
  long bytes;
  long spheres;
  long cylinders;
  long cones;
  std::map<int, long> polygons;  // by vertex count
  long patches;
  long lights;
  long f_lines;
  long distinct_f;
  const char* bbox_min;
  const char* bbox_max;
};

void PrintTo(const Row& row, std::ostream* os) { *os << row.scene << " -s " << row.size; }

// clang-format off
const std::vector<Row> kTable{
  // scene   -s  lines  bytes    sph   cyl   cone  polygons                 pp    l  f    df  bbox min                     bbox max
  {"balls",  1,  28,    619,     10,   0,    0,    {{4, 1}},                0,    3, 2,   2,  "-12 -12 -0.5",              "12 12 0.710998"},
  {"balls",  2,  109,   3884,    91,   0,    0,    {{4, 1}},                0,    3, 2,   2,  "-12 -12 -0.5",              "12 12 0.785072"},
  {"balls",  3,  838,   33349,   820,  0,    0,    {{4, 1}},                0,    3, 2,   2,  "-12 -12 -0.5",              "12 12 0.821994"},
  {"balls",  4,  7399,  305317,  7381, 0,    0,    {{4, 1}},                0,    3, 2,   2,  "-12 -12 -0.5",              "12 12 0.830567"},
  {"gears",  1,  1030,  19765,   0,    0,    0,    {{4, 145}, {144, 2}},    0,    5, 2,   2,  "-2 -2 0",                   "2 2 1"},
  {"gears",  2,  8107,  161775,  0,    0,    0,    {{4, 1153}, {144, 16}},  0,    5, 9,   8,  "-2 -2 0",                   "2 2 1"},
  {"gears",  3,  27316, 623198,  0,    0,    0,    {{4, 3889}, {144, 54}},  0,    5, 28,  27, "-2 -2 0",                   "2 2 1"},
  {"gears",  4,  64723, 1335003, 0,    0,    0,    {{4, 9217}, {144, 128}}, 0,    5, 65,  63, "-2 -2 0",                   "2 2 1"},
  {"mount",  1,  47,    627,     4,    0,    0,    {{3, 8}},                0,    1, 2,   2,  "-1.15961 -1 -0.5481",       "1 1.15961 1.37821"},
  {"mount",  2,  143,   1950,    4,    0,    0,    {{3, 32}},               0,    1, 2,   2,  "-1.15961 -1 -0.567592",     "1 1.15961 1.37821"},
  {"mount",  3,  527,   7860,    4,    0,    0,    {{3, 128}},              0,    1, 2,   2,  "-1.15961 -1 -0.702953",     "1 1.15961 1.37821"},
  {"mount",  6,  32783, 632253,  4,    0,    0,    {{3, 8192}},             0,    1, 2,   2,  "-1.15961 -1 -0.702953",     "1 1.15961 1.37821"},
  {"rings",  1,  83,    3507,    30,   30,   0,    {{4, 1}},                0,    3, 7,   7,  "-4.27965 1.65358 -2.77965", "2.27965 5.22625 3.77965"},
  {"rings",  2,  347,   15627,   150,  150,  0,    {{4, 1}},                0,    3, 31,  7,  "-5.37286 1.65358 -3.87286", "3.37286 7.83938 4.87286"},
  {"rings",  3,  941,   43068,   420,  420,  0,    {{4, 1}},                0,    3, 85,  7,  "-6.46608 1.65358 -4.96608", "4.46608 10.4525 5.96608"},
  {"rings",  7,  9257,  421988,  4200, 4200, 0,    {{4, 1}},                0,    3, 841, 7,  "-10.8389 1.65358 -9.33895", "8.83895 20.905 10.3389"},
  {"teapot", 1,  242,   5097,    0,    0,    0,    {{4, 1}},                56,   2, 3,   3,  "-4 -4 0",                   "4 4 3.15"},
  {"teapot", 2,  993,   30915,   0,    0,    0,    {{4, 4}},                240,  2, 3,   3,  "-4 -4 0",                   "4 4 3.15"},
  {"teapot", 3,  2266,  82599,   0,    0,    0,    {{4, 9}},                552,  2, 3,   3,  "-4 -4 0",                   "4 4 3.15"},
  {"teapot", 6,  9217,  360747,  0,    0,    0,    {{4, 36}},               2256, 2, 3,   3,  "-4 -4 0",                   "4 4 3.15"},
  {"teapot", 12, 37213, 1508322, 0,    0,    0,    {{4, 144}},              9120, 2, 3,   3,  "-4 -4 0",                   "4 4 3.15"},
  {"tetra",  1,  26,    298,     0,    0,    0,    {{3, 4}},                0,    1, 1,   1,  "-1 -1 -1",                  "1 1 1"},
  {"tetra",  2,  74,    580,     0,    0,    0,    {{3, 16}},               0,    1, 1,   1,  "-1 -1 -1",                  "1 1 1"},
  {"tetra",  3,  266,   2392,    0,    0,    0,    {{3, 64}},               0,    1, 1,   1,  "-1 -1 -1",                  "1 1 1"},
  {"tetra",  6,  16394, 255616,  0,    0,    0,    {{3, 4096}},             0,    1, 1,   1,  "-1 -1 -1",                  "1 1 1"},
  {"tree",   1,  28,    500,     3,    0,    3,    {{4, 1}},                0,    7, 2,   2,  "-50 -50 0",                 "50 50 1.70175"},
  {"tree",   2,  36,    960,     7,    0,    7,    {{4, 1}},                0,    7, 2,   2,  "-50 -50 0",                 "50 50 2.13826"},
  {"tree",   3,  52,    1874,    15,   0,    15,   {{4, 1}},                0,    7, 2,   2,  "-50 -50 0",                 "50 50 2.46311"},
  {"tree",   11, 8212,  475128,  4095, 0,    4095, {{4, 1}},                0,    7, 2,   2,  "-50 -50 0",                 "50 50 3.13749"},
};
// clang-format on

std::string row_name(const testing::TestParamInfo<Row>& info) {
  return std::string(info.param.scene) + "_s" + std::to_string(info.param.size);
}

long polygon_total(const std::map<int, long>& by_count) {
  long total = 0;
  for (const auto& [vertices, count] : by_count) total += count;
  return total;
}

class ClassicSceneTable : public testing::TestWithParam<Row> {
 protected:
  const std::string& text() const { return generated(GetParam().scene, GetParam().size); }
};

TEST_P(ClassicSceneTable, TableACountsAndBytes) {
  const Row& row = GetParam();
  const NffSummary s = summarize_nff(text());
  EXPECT_EQ(s.lines, row.lines);
  EXPECT_EQ(s.bytes, row.bytes) << "bytes differ: output is not bit-identical to the SPD's";
  EXPECT_EQ(s.spheres, row.spheres);
  EXPECT_EQ(s.cylinders, row.cylinders);
  EXPECT_EQ(s.cones, row.cones);
  EXPECT_EQ(s.polygons, polygon_total(row.polygons));
  EXPECT_EQ(s.polygons_by_vertex_count, row.polygons);
  EXPECT_EQ(s.patches, row.patches);
  EXPECT_EQ(s.lights, row.lights);
  EXPECT_EQ(s.f_lines, row.f_lines);
  EXPECT_EQ(static_cast<long>(s.distinct_f.size()), row.distinct_f);
}

TEST_P(ClassicSceneTable, TableBBoundingBox) {
  const NffSummary s = summarize_nff(text());
  EXPECT_EQ(format_corner(s.bbox_min), GetParam().bbox_min);
  EXPECT_EQ(format_corner(s.bbox_max), GetParam().bbox_max);
}

// Table C: the `b` line and the 6 view lines, the same at every size for these scenes.
struct ViewRow {
  const char* from;
  const char* at;
  const char* up;
  const char* hither;
};

const std::map<std::string_view, ViewRow> kViews{
    {"balls", {"2.1 1.3 1.7", "0 0 0", "0 0 1", "0.01"}},
    {"gears", {"-1.1 -2.1 2.6", "0 0 0", "0 0 1", "1"}},
    {"mount", {"-1.6 1.6 1.7", "0 0 0", "0 0 1", "0.01"}},
    {"rings", {"-1 -2.61313 0.5", "-1 -1.61313 0.5", "0 0 1", "1"}},
    {"teapot", {"4.86 7.2 5.4", "0 0 0", "0 0 1", "1"}},
    {"tetra",
     {"1.02285 -3.17715 -2.17451", "-0.004103 -0.004103 0.216539", "-0.816497 -0.816497 0.816497",
      "1"}},
    {"tree", {"4.5 0.4 2", "0 0 1.5", "0 0 1", "1"}},
};

TEST_P(ClassicSceneTable, TableCBackgroundAndView) {
  const NffSummary s = summarize_nff(text());
  const ViewRow& v = kViews.at(GetParam().scene);
  EXPECT_EQ(s.background_line, "b 0.078 0.361 0.753");
  const std::vector<std::string> expected{
      std::string("from ") + v.from,     std::string("at ") + v.at,
      std::string("up ") + v.up,         "angle 45",
      std::string("hither ") + v.hither, "resolution 512 512"};
  EXPECT_EQ(s.view_lines, expected);
  // §1.5: `b` first, then the 7-line view block.
  EXPECT_EQ(text().rfind("b 0.078 0.361 0.753\nv\nfrom ", 0), 0U);
}

// Table D for gears lists the ground line and gear (0,0,0)'s line; every other line must be one
// of the two per-gear forms (§3.2), transparent or opaque.
void expect_gears_materials(const std::set<std::string>& lines) {
  const std::string ground = "f 1 0.85 0.7 0.3 0.6 3.0827 0 0";
  EXPECT_TRUE(lines.contains(ground));
  EXPECT_TRUE(lines.contains("f 1 0.605523 0.408284 0.2 0 100000 0.8 1.1"));
  for (const std::string& line : lines) {
    if (line == ground) continue;
    const bool transparent = line.ends_with(" 0.2 0 100000 0.8 1.1");
    const bool opaque = line.ends_with(" 1 0 100000 0 0");
    EXPECT_TRUE(transparent || opaque) << line;
  }
}

// Table D: the distinct `f` lines exactly as written.
const std::map<std::string_view, std::set<std::string>> kMaterials{
    {"balls", {"f 1 0.75 0.33 0.8 0 100000 0 1", "f 1 0.9 0.7 0.5 0.5 3.0827 0 1"}},
    {"mount", {"f 1 1 1 0.1 0.1 101.148 0.9 1.5", "f 0.5 0.45 0.35 1 0 100000 0 0"}},
    {"rings",
     {"f 1 1 1 1 0 100000 0 0", "f 1 0 0 0.5 0.2 3.0827 0 0", "f 0 1 0 0.5 0.2 3.0827 0 0",
      "f 0 0 1 0.5 0.2 3.0827 0 0", "f 0 1 1 0.5 0.2 3.0827 0 0", "f 1 0 1 0.5 0.2 3.0827 0 0",
      "f 1 1 0 0.5 0.2 3.0827 0 0"}},
    {"teapot",
     {"f 1 1 1 0.5 0.5 4.81884 0 0", "f 0.5 0.5 0.5 0.5 0.5 4.81884 0 0",
      "f 1 0.5 0.1 0.75 0.25 3.0827 0 0"}},
    {"tetra", {"f 1 0.2 0.2 1 0 100000 0 0"}},
    {"tree", {"f 0.2 0.7 0.2 1 0 100000 0 0", "f 0.55 0.4 0.2 1 0 100000 0 0"}},
};

TEST_P(ClassicSceneTable, TableDDistinctMaterials) {
  const std::set<std::string> lines = summarize_nff(text()).distinct_f;
  if (std::string_view(GetParam().scene) == "gears") {
    expect_gears_materials(lines);
  } else {
    EXPECT_EQ(lines, kMaterials.at(GetParam().scene));
  }
}

INSTANTIATE_TEST_SUITE_P(SpdTables, ClassicSceneTable, testing::ValuesIn(kTable), row_name);

// §8: every generator is deterministic; two runs at the default size give the same bytes.
TEST(ClassicScenes, GenerationIsDeterministic) {
  const std::map<std::string_view, int> kDefaultSizes{{"balls", 4}, {"gears", 4},  {"mount", 6},
                                                      {"rings", 7}, {"teapot", 6}, {"tetra", 6},
                                                      {"tree", 11}};
  for (const auto& [scene, size] : kDefaultSizes) {
    EXPECT_EQ(generate(scene, size), generated(scene, size)) << scene;
  }
}

}  // namespace
}  // namespace raygate::test
