// Roles, document kinds, scene statuses and verdicts are enums (core/domain.h, gate/verdict.h,
// measure/change.h, compare/image_verdict.h); their words belong where a document or a store
// row is read or written. This test reads every source file under harness/ and fails on any
// comparison of a value with one of those words as a string literal (`kind == "compare"`,
// `"head" != role`) outside those readers and writers, naming FILE:LINE, so a new branch on a
// word cannot come back unnoticed. Comparisons with other words (option values, /proc keys,
// URL parameters) are not the domain's and stay allowed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/domain.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

// The domain's words: roles, document kinds, scene statuses, change, speed and image verdicts,
// gate outcomes and bisect steps. A word here that is also an option value elsewhere is still
// refused: the option's parser compares against its enum's to_string, as the domain's do.
const std::vector<std::string>& domain_words() {
  static const std::vector<std::string> words{
      "baseline",   "tracer",   "base",      "head",         "golden",  // roles, image references
      "run",        "compare",                                          // document kinds
      "measured",   "failed",                                           // scene statuses
      "UNCHANGED",  "IMPROVED", "REGRESSED", "INCONCLUSIVE",            // change verdicts
      "MEASURED",   "FAILED",                                           // speed verdicts
      "pass",       "warn",     "fail",      "missing",      "error",
      "unmeasured",                          // image verdicts, outcomes
      "good",       "bad",      "skipped"};  // bisect steps
  return words;
}

// The readers and writers of the words, relative to harness/: the results document's JSON and
// its checker, and the tables that spell each enum once. (The store writes rows from
// to_string() and reads none of these words back into records.)
const std::set<std::string>& boundary_files() {
  static const std::set<std::string> files{"results/results_json.cpp", "results/results_check.cpp",
                                           "core/domain.cpp"};
  return files;
}

// `text` with // and /* */ comments blanked out (newlines kept, so line numbers stay), string
// and character literals left as they are: a comment that quotes a comparison is not one.
std::string without_comments(const std::string& text) {
  std::string out = text;
  enum class State { code, string, character, line_comment, block_comment } state = State::code;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const char c = out[i];
    const char next = i + 1 < out.size() ? out[i + 1] : '\0';
    switch (state) {
      case State::code:
        if (c == '"') state = State::string;
        if (c == '\'') state = State::character;
        if (c == '/' && next == '/') state = State::line_comment;
        if (c == '/' && next == '*') state = State::block_comment;
        if (state == State::line_comment || state == State::block_comment) out[i] = ' ';
        break;
      case State::string:
      case State::character:
        if (c == '\\') {
          ++i;
        } else if (c == (state == State::string ? '"' : '\'')) {
          state = State::code;
        }
        break;
      case State::line_comment:
        if (c == '\n') {
          state = State::code;
        } else {
          out[i] = ' ';
        }
        break;
      case State::block_comment:
        if (c == '*' && next == '/') {
          out[i] = out[i + 1] = ' ';
          ++i;
          state = State::code;
        } else if (c != '\n') {
          out[i] = ' ';
        }
        break;
    }
  }
  return out;
}

// "LINE: the comparison" for each comparison with a domain word in `source`.
std::vector<std::string> word_comparisons(const std::string& source) {
  std::string alternatives;
  for (const std::string& word : domain_words()) {
    alternatives += (alternatives.empty() ? "" : "|") + word;
  }
  const std::regex comparison("(==|!=)\\s*\"(" + alternatives + ")\"|\"(" + alternatives +
                              ")\"\\s*(==|!=)");
  const std::string code = without_comments(source);
  std::vector<std::string> found;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), comparison);
       it != std::sregex_iterator(); ++it) {
    const auto at = code.begin() + it->position();
    const long line = 1 + std::count(code.begin(), at, '\n');
    found.push_back(std::to_string(line) + ": " + it->str());
  }
  return found;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// harness/ of this checkout; RAYGATE_DOMAIN_SCAN_DIR names another (to check an older tree).
fs::path harness_dir() {
  if (const char* other = std::getenv("RAYGATE_DOMAIN_SCAN_DIR"); other && *other) return other;
  return fs::path(RAYGATE_SOURCE_DIR) / "harness";
}

TEST(DomainWordsTest, FindsComparisonsWithTheWordsEitherWayRound) {
  const std::vector<std::string> found = word_comparisons(
      "if (document.kind == \"compare\") return;\n"
      "bool b = \"head\" != role;\n"
      "x = gate.speed ==\n    \"REGRESSED\";\n");
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0], "1: == \"compare\"");
  EXPECT_EQ(found[1], "2: \"head\" !=");
  EXPECT_EQ(found[2].substr(0, 2), "3:");
}

TEST(DomainWordsTest, LeavesOtherWordsCommentsAndWordsThatAreNotCompared) {
  EXPECT_TRUE(word_comparisons("if (args.format == \"json\") {}\n").empty());
  EXPECT_TRUE(word_comparisons("// old: kind == \"compare\"\n/* role != \"head\" */\n").empty());
  EXPECT_TRUE(word_comparisons("const char* role = \"head\";\nf(\"tracer\");\n").empty());
  EXPECT_TRUE(word_comparisons("if (name == \"headless\") {}\n").empty());
  // A quote inside a literal does not open a comment or end the scan early.
  EXPECT_EQ(word_comparisons("s = \"a // b\"; if (k == \"run\") {}\n").size(), 1u);
}

TEST(DomainWordsTest, NoSourceOutsideTheReadersAndWritersComparesWithADomainWord) {
  const fs::path root = harness_dir();
  ASSERT_TRUE(fs::is_directory(root)) << root;
  std::size_t files = 0;
  std::vector<std::string> offences;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root)) {
    const fs::path& path = entry.path();
    if (!entry.is_regular_file() || (path.extension() != ".cpp" && path.extension() != ".h")) {
      continue;
    }
    ++files;
    const std::string relative = path.lexically_relative(root).generic_string();
    if (boundary_files().contains(relative)) continue;
    for (const std::string& hit : word_comparisons(read_text(path))) {
      offences.push_back("harness/" + relative + ":" + hit);
    }
  }
  EXPECT_GT(files, 100u) << "too few sources under " << root;
  std::string list;
  for (const std::string& offence : offences) list += "\n  " + offence;
  EXPECT_TRUE(offences.empty())
      << offences.size() << " comparisons with a domain word as a string; compare the enum "
      << "(core/domain.h) and keep the word to the JSON/SQL readers and writers:" << list;
}

TEST(DomainWordsTest, EveryWordReadsBackAsItsEnum) {
  for (const Role role : {Role::baseline, Role::tracer, Role::base, Role::head}) {
    EXPECT_EQ(parse_role(to_string(role)), role);
  }
  for (const DocumentKind kind : {DocumentKind::run, DocumentKind::compare}) {
    EXPECT_EQ(parse_document_kind(to_string(kind)), kind);
  }
  for (const SceneStatus status : {SceneStatus::measured, SceneStatus::failed}) {
    EXPECT_EQ(parse_scene_status(to_string(status)), status);
  }
  EXPECT_EQ(parse_role("Head"), std::nullopt);
  EXPECT_EQ(parse_document_kind("merge"), std::nullopt);
  EXPECT_EQ(revision_roles(DocumentKind::compare), (std::vector<Role>{Role::base, Role::head}));
  EXPECT_EQ(primary_role(DocumentKind::run), Role::tracer);
}

}  // namespace
}  // namespace raygate
