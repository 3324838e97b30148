// Text from a repository enters raygate as valid UTF-8: a Latin-1 commit (i18n.commitEncoding)
// decoded by its header, other invalid bytes replaced, branch and tag names repaired, and the
// Revision of such a commit written into a results document without throwing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "checkout/git_fixture.h"
#include "checkout/repository.h"
#include "checkout/resolve.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/utf8.h"

namespace raygate {
namespace {

const std::string kFffd(kReplacementCharacter);

class CheckoutCommitText : public ::testing::Test {
 protected:
  CheckoutCommitText() : repo_(dir_.path() / "tracer") {
    repo_.write("main.cpp", "int main() {}\n");
    repo_.commit("first");
  }

  Repository open() const { return Repository::open(repo_.path().string(), dir_.path() / "c"); }

  TempDir dir_{"raygate-commit-text"};
  testing::GitFixture repo_;
};

TEST_F(CheckoutCommitText, ALatin1CommitIsDecodedByItsEncodingHeader) {
  testing::CommitOptions latin1;
  latin1.encoding = "ISO-8859-1";
  latin1.author = "Ren\xE9 M\xFCller";
  const std::string sha = repo_.commit("Caf\xE9: faster cr\xE8me shading", latin1);
  const Revision revision = open().resolve(sha);
  EXPECT_EQ(revision.subject, "Caf\xC3\xA9: faster cr\xC3\xA8me shading");
  EXPECT_EQ(revision.author, "Ren\xC3\xA9 M\xC3\xBCller");
}

TEST_F(CheckoutCommitText, EveryLatin1SpellingOfTheHeaderIsHonoured) {
  for (const char* name : {"latin1", "iso8859-1", "ISO_8859-1", "LATIN-1", "l1", "CP819"}) {
    testing::CommitOptions options;
    options.encoding = name;
    const std::string sha = repo_.commit("na\xEFve", options);
    EXPECT_EQ(open().resolve(sha).subject, "na\xC3\xAFve") << name;
  }
}

TEST_F(CheckoutCommitText, InvalidBytesWithoutAHeaderAreReplacedNotRejected) {
  testing::CommitOptions options;
  options.author = "Bj\xF6rn";
  const std::string sha = repo_.commit("Caf\xE9 \xC0\xAF and \xE2\x82\xAC kept", options);
  const Revision revision = open().resolve(sha);
  EXPECT_EQ(revision.subject, "Caf" + kFffd + " " + kFffd + kFffd + " and \xE2\x82\xAC kept");
  EXPECT_EQ(revision.author, "Bj" + kFffd + "rn");
}

TEST_F(CheckoutCommitText, AnotherDeclaredEncodingIsRepairedNotTrusted) {
  // Shift-JIS is not decoded (only Latin-1 is): its bytes that are not UTF-8 become U+FFFD.
  testing::CommitOptions options;
  options.encoding = "Shift_JIS";
  const std::string sha = repo_.commit("\x93\xfa\x96\x7b fix", options);
  const Revision revision = open().resolve(sha);
  EXPECT_TRUE(is_valid_utf8(revision.subject));
  EXPECT_TRUE(revision.subject.ends_with(" fix"));
}

TEST_F(CheckoutCommitText, UtfEightCommitsAreKeptExactly) {
  testing::CommitOptions options;
  options.encoding = "UTF-8";
  options.author = "\xE5\xB1\xB1\xE7\x94\xB0";
  const std::string sha = repo_.commit("\xF0\x9F\x90\xA2 BVH: 12% faster", options);
  const Revision revision = open().resolve(sha);
  EXPECT_EQ(revision.subject, "\xF0\x9F\x90\xA2 BVH: 12% faster");
  EXPECT_EQ(revision.author, "\xE5\xB1\xB1\xE7\x94\xB0");
}

TEST_F(CheckoutCommitText, BranchAndTagNamesOfAnyBytesAreRepaired) {
  repo_.branch("caf\xE9");
  repo_.tag("v\xFF");
  const Revision revision = open().resolve("caf\xE9");  // found by its bytes
  EXPECT_EQ(revision.ref_name, "refs/heads/caf" + kFffd);
  EXPECT_EQ(revision.revision, "caf" + kFffd);
  EXPECT_EQ(git::branch_names(repo_.raw()), (std::vector<std::string>{"caf" + kFffd, "main"}));
  EXPECT_EQ(git::tag_names(repo_.raw()), std::vector<std::string>{"v" + kFffd});
  try {
    open().resolve("nope");
    ADD_FAILURE() << "an unknown revision was resolved";
  } catch (const UsageError& e) {
    EXPECT_TRUE(is_valid_utf8(e.what())) << e.what();
  }
}

TEST_F(CheckoutCommitText, TheRevisionOfABadlyEncodedCommitSerializesAsJson) {
  // What lost the measurement: nlohmann::json throws type_error.316 when it dumps invalid UTF-8.
  testing::CommitOptions options;
  options.author = "\xFF\xFE";
  const std::string sha = repo_.commit("\x1b[31m red \xE9", options);
  const Worktree tree = open().checkout(sha);
  const nlohmann::json record = {{"subject", tree.subject}, {"author", tree.author}};
  EXPECT_NO_THROW((void)record.dump());
}

}  // namespace
}  // namespace raygate
