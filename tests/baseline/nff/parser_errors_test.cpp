// The NFF reader on bad input: each case asserts the exact message, location included, so a
// change of wording or a column off by one fails here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>

#include "nff/parser.h"

namespace raygate::nff {
namespace {

// A valid view and material on lines 1-6, so the entity under test starts on line 7.
const std::string kHead = "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 45\nf 1 0 0 1 0 1 0 1\n";
const std::string kView = "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 45\n";

struct BadInput {
  const char* name;
  std::string text;
  std::string message;  // the whole what()
};

// Names the case in gtest's output instead of dumping its bytes.
void PrintTo(const BadInput& input, std::ostream* out) { *out << input.name; }

std::string message_of(const std::string& text) {
  try {
    parse_nff(text, "t.nff");
  } catch (const ParseError& error) {
    return error.what();
  }
  return "(no error)";
}

class NffParserError : public testing::TestWithParam<BadInput> {};

TEST_P(NffParserError, ExactMessage) {
  const BadInput& input = GetParam();
  EXPECT_EQ(message_of(input.text), input.message);
}

// detail() and loc() agree with what().
TEST_P(NffParserError, PartsAgreeWithMessage) {
  const BadInput& input = GetParam();
  try {
    parse_nff(input.text, "t.nff");
    FAIL() << "no error";
  } catch (const ParseError& error) {
    EXPECT_EQ(error.loc().path, "t.nff");
    const std::string prefix = "t.nff:" + std::to_string(error.loc().line) + ":" +
                               std::to_string(error.loc().column) + ": ";
    EXPECT_EQ(prefix + error.detail(), error.what());
  }
}

const BadInput kBadInputs[] = {
    // Empty and truncated files.
    {"Empty", "", "t.nff:1:1: expected an NFF scene, found an empty file"},
    {"OnlyComments", "# nothing\n  \n", "t.nff:3:1: expected an NFF scene, found an empty file"},
    {"TruncatedMidSphere", kHead + "s 0 0",
     "t.nff:7:6: expected the z of the centre of sphere (s), found end of file"},
    {"TruncatedAfterNewline", kHead + "s 0 0 0\n",
     "t.nff:8:1: expected the radius of sphere (s), found end of file"},
    {"TruncatedMaterial", kView + "f 1 1 1 1 0 1 0",
     "t.nff:6:16: expected the ior of fill material (f), found end of file"},
    {"TruncatedLightColour", kHead + "l 1 2 3 0.5 0.5",
     "t.nff:7:16: expected the blue of the colour of light (l), found end of file"},
    {"TruncatedView", "v\nfrom 0 0",
     "t.nff:2:9: expected the z of 'from' in view (v), found end of file"},
    // Not a number.
    {"WordForNumber", kHead + "s 0 0 0 abc\n",
     "t.nff:7:9: expected the radius of sphere (s), found 'abc'"},
    {"KeywordForNumber", kView + "f 1 1 1 1 0 1 0\ns 0 0 0 1\n",
     "t.nff:7:1: expected the ior of fill material (f), found 's'"},
    {"BackgroundWord", "b 0 zero 0\n",
     "t.nff:1:5: expected the green of background (b), found 'zero'"},
    {"TwoDots", kHead + "s 0 1.5.2 0 1\n",
     "t.nff:7:5: expected the y of the centre of sphere (s), found '1.5.2'"},
    // Vertex counts that do not match the vertices.
    {"TooFewVertices", kHead + "p 4\n0 0 0\n1 0 0\n1 1 0\ns 0 0 0 1\n",
     "t.nff:11:1: expected the x of vertex 4 of 4 of polygon (p), found 's'"},
    {"TooManyVertices", kHead + "p 3\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n",
     "t.nff:11:1: expected an NFF keyword (v, b, l, f, c, s, p, pp), found '0' (one number too "
     "many for the polygon (p) at line 7?)"},
    {"HugeCount", kHead + "p 2000000000\n0 0 0\n",
     "t.nff:9:1: expected the x of vertex 2 of 2000000000 of polygon (p), found end of file"},
    {"CountBeyondInt", kHead + "pp 3000000000\n",
     "t.nff:7:4: expected the vertex count of patch (pp) as an integer of at most 2147483647, "
     "found '3000000000'"},
    {"CountTwo", kHead + "p 2\n0 0 0\n1 0 0\n",
     "t.nff:7:3: expected the vertex count of polygon (p) as an integer of at least 3, found '2'"},
    {"CountNotInteger", kHead + "p 3.0\n",
     "t.nff:7:3: expected the vertex count of polygon (p) as an integer of at least 3, found "
     "'3.0'"},
    {"CountMissing", kHead + "p s 0 0 0 1\n",
     "t.nff:7:3: expected the vertex count of polygon (p) as an integer of at least 3, found 's'"},
    // Numbers that are not finite.
    {"NaN", kHead + "s 0 nan 0 1\n",
     "t.nff:7:5: expected the y of the centre of sphere (s) as a finite number, found 'nan'"},
    {"NaNMixedCase", kHead + "s 0 0 NaN 1\n",
     "t.nff:7:7: expected the z of the centre of sphere (s) as a finite number, found 'NaN'"},
    {"Inf", kHead + "c 0 0 0 1 0 0 1 inf\n",
     "t.nff:7:17: expected the apex radius of cone (c) as a finite number, found 'inf'"},
    {"MinusInfinity", "b -Infinity 0 0\n",
     "t.nff:1:3: expected the red of background (b) as a finite number, found '-Infinity'"},
    {"Overflow", kHead + "s 0 0 0 1e999\n",
     "t.nff:7:9: expected the radius of sphere (s) as a finite number, found '1e999'"},
    // Degenerate primitives.
    {"ZeroRadius", kHead + "s 0 0 0 0\n",
     "t.nff:7:9: expected a non-zero radius of sphere (s), found '0'"},
    {"MinusZeroRadius", kHead + "s 0 0 0 -0.0\n",
     "t.nff:7:9: expected a non-zero radius of sphere (s), found '-0.0'"},
    {"ConeSameEnds", kHead + "c 1 2 3 1 1 2 3 0.5\n",
     "t.nff:7:11: expected the apex of cone (c) away from its base, found the same point"},
    {"ConeZeroRadii", kHead + "c 0 0 0 0 0 0 1 0\n",
     "t.nff:7:17: expected a non-zero radius of cone (c), found '0' and '0'"},
    {"ConeMixedSigns", kHead + "c 0 0 0 1 0 0 1 -1\n",
     "t.nff:7:17: expected radii of cone (c) of the same sign, found '1' and '-1'"},
    {"PolygonTwoDistinct", kHead + "p 3\n0 0 0\n1 0 0\n0 0 0\n",
     "t.nff:7:1: expected at least 3 distinct vertices in polygon (p), found 2"},
    {"PolygonOneDistinct", kHead + "p 4\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n",
     "t.nff:7:1: expected at least 3 distinct vertices in polygon (p), found 1"},
    {"PolygonCollinear", kHead + "p 4\n0 0 0\n1 1 1\n3 3 3\n2 2 2\n",
     "t.nff:7:1: expected polygon (p) with non-zero area, found collinear vertices"},
    {"PolygonCollinearRounded", kHead + "p 3\n0.1 0.2 0.3\n0.2 0.4 0.6\n0.3 0.6 0.9\n",
     "t.nff:7:1: expected polygon (p) with non-zero area, found collinear vertices"},
    {"PolygonFigureEight", kHead + "p 4\n0 0 0\n1 1 0\n1 0 0\n0 1 0\n",
     "t.nff:7:1: expected polygon (p) with non-zero area, found a net area of zero"},
    {"PatchZeroNormal", kHead + "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 0\n0 1 0 0 0 1\n",
     "t.nff:9:7: expected a non-zero normal of vertex 2 of 3 of patch (pp), found a zero vector"},
    // The view.
    {"MissingView", "f 1 1 1 1 0 1 0 1\ns 0 0 0 1\n",
     "t.nff:3:1: expected a view (v), found end of file"},
    {"SecondView", kHead + "v\nfrom 0 0 1\n",
     "t.nff:7:1: expected one view (v), found a second 'v' (the first is at line 1, column 1)"},
    {"ViewMissingUp", "v\nfrom 0 0 -5\nat 0 0 0\nangle 45\nf 1 1 1 1 0 1 0 1\n",
     "t.nff:5:1: expected 'up' in view (v), found 'f'"},
    {"ViewMissingAngleAtEnd", "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\n",
     "t.nff:5:1: expected 'angle' in view (v), found end of file"},
    {"ViewKeywordTwice", "v\nfrom 0 0 -5\nfrom 0 0 1\n",
     "t.nff:3:1: expected each view keyword once, found a second 'from'"},
    {"ViewKeywordMisspelt", "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangel 45\n",
     "t.nff:5:1: expected a view keyword (from, at, up, angle, hither, resolution), found "
     "'angel'; did you mean 'angle'?"},
    {"ViewKeywordCase", "v\nFrom 0 0 -5\n",
     "t.nff:2:1: expected a view keyword (from, at, up, angle, hither, resolution), found "
     "'From'; did you mean 'from'?"},
    {"ViewKeywordWithoutView", "from 0 0 -5\n",
     "t.nff:1:1: expected an NFF keyword (v, b, l, f, c, s, p, pp), found 'from'; view keywords "
     "belong after a 'v'"},
    {"ObjectBeforeMaterial", kView + "s 0 0 0 1\n",
     "t.nff:6:1: expected a fill material (f) before the first object, found 's'"},
    {"ResolutionZero", kView + "resolution 0 512\n",
     "t.nff:6:12: expected the width of the resolution of view (v) as an integer from 1 to 16384, "
     "found '0'"},
    {"ResolutionTooLarge", kView + "resolution 512 16385\n",
     "t.nff:6:16: expected the height of the resolution of view (v) as an integer from 1 to "
     "16384, found '16385'"},
    {"ResolutionNotInteger", kView + "resolution 512.5 512\n",
     "t.nff:6:12: expected the width of the resolution of view (v) as an integer from 1 to 16384, "
     "found '512.5'"},
    {"AngleZero", "v\nangle 0\n",
     "t.nff:2:7: expected the angle of view (v) in degrees, above 0 and below 180, found '0'"},
    {"Angle180", "v\nangle 180\n",
     "t.nff:2:7: expected the angle of view (v) in degrees, above 0 and below 180, found '180'"},
    {"AngleNegative", "v\nangle -45\n",
     "t.nff:2:7: expected the angle of view (v) in degrees, above 0 and below 180, found '-45'"},
    {"HitherNegative", kView + "hither -1\n",
     "t.nff:6:8: expected the hither of view (v) as 0 or more, found '-1'"},
    // Unknown keywords, with and without a suggestion.
    {"Sphere", kHead + "sphere 0 0 0 1\n",
     "t.nff:7:1: expected an NFF keyword (v, b, l, f, c, s, p, pp), found 'sphere'; did you mean "
     "'s'?"},
    {"UpperCase", kHead + "PP 3\n",
     "t.nff:7:1: expected an NFF keyword (v, b, l, f, c, s, p, pp), found 'PP'; did you mean "
     "'pp'?"},
    {"Cylindre", kHead + "cylindre 0 0 0 1 0 0 1 1\n",
     "t.nff:7:1: expected an NFF keyword (v, b, l, f, c, s, p, pp), found 'cylindre'; did you "
     "mean 'c'?"},
    {"NoSuggestion", kHead + "xyz\n",
     "t.nff:7:1: expected an NFF keyword (v, b, l, f, c, s, p, pp), found 'xyz'"},
    {"LongToken", kHead + std::string(50, 'q') + "\n",
     "t.nff:7:1: expected an NFF keyword (v, b, l, f, c, s, p, pp), found '" +
         std::string(40, 'q') + "...'"},
    // Binary garbage: control bytes are reported as hex, at their own column.
    {"NulInNumber", kHead + "s 0 0" + std::string(1, '\0') + " 0 1\n",
     "t.nff:7:6: expected the y of the centre of sphere (s), found byte 0x00"},
    {"ControlBytesAtStart", "\x01\x02\x03",
     "t.nff:1:1: expected an NFF keyword (v, b, l, f, c, s, p, pp), found byte 0x01"},
    {"ControlByteInKeyword", kHead + "s\x7f 0 0 0 1\n",
     "t.nff:7:2: expected an NFF keyword (v, b, l, f, c, s, p, pp), found byte 0x7f"},
    {"HighBytes", "\xff\xfe\x80v\n",
     "t.nff:1:1: expected an NFF keyword (v, b, l, f, c, s, p, pp), found '\\xff\\xfe\\x80v'"},
    {"ControlByteInView", "v\nfrom 0 0 1\n\x1b[0m\n",
     "t.nff:3:1: expected a view keyword (from, at, up, angle, hither, resolution), found byte "
     "0x1b"},
};

INSTANTIATE_TEST_SUITE_P(BadInputs, NffParserError, testing::ValuesIn(kBadInputs),
                         [](const testing::TestParamInfo<BadInput>& case_info) {
                           return std::string(case_info.param.name);
                         });

// Problems with the file itself: no line or column, but the path prefix stays.
std::string file_message(const std::string& path) {
  try {
    read_nff_file(path);
  } catch (const ParseError& error) {
    EXPECT_EQ(error.loc().line, 0);
    EXPECT_EQ(error.loc().path, path);
    return error.what();
  }
  return "(no error)";
}

TEST(NffReadFile, MissingFile) {
  EXPECT_EQ(file_message("/nonexistent/raygate/scene.nff"),
            "/nonexistent/raygate/scene.nff: expected a readable NFF file, found no such file");
}

TEST(NffReadFile, Directory) {
  const std::string dir = std::filesystem::temp_directory_path().string();
  EXPECT_EQ(file_message(dir), dir + ": expected a readable NFF file, found a directory");
}

TEST(NffReadFile, Device) {
  EXPECT_EQ(
      file_message("/dev/zero"),
      "/dev/zero: expected a readable NFF file, found a device or socket, not a regular file");
}

TEST(NffReadFile, Unreadable) {
  if (::geteuid() == 0) GTEST_SKIP() << "root can read any file";
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("raygate_nff_unreadable_" + std::to_string(::getpid()));
  std::ofstream(path) << "v\n";
  std::filesystem::permissions(path, std::filesystem::perms::none);
  const std::string message = file_message(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(message, path.string() +
                         ": expected a readable NFF file, found a file it cannot open (Permission "
                         "denied)");
}

TEST(NffReadFile, ErrorInsideFileHasItsPath) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("raygate_nff_bad_" + std::to_string(::getpid()) + ".nff");
  std::ofstream(path) << kHead << "s 0 0 0 0\n";
  std::string message = "(no error)";
  try {
    read_nff_file(path.string());
  } catch (const ParseError& error) {
    message = error.what();
  }
  std::filesystem::remove(path);
  EXPECT_EQ(message, path.string() + ":7:9: expected a non-zero radius of sphere (s), found '0'");
}

}  // namespace
}  // namespace raygate::nff
