// Names from suites, adapters, results documents and stores never become paths outside the
// folder they belong in: every entry point refuses such a name with exit 2 naming the field, and
// writes nothing (core/path_component.h). Each case would have written outside its folder once.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <string>
#include <vector>

#include "cli_support.h"
#include "results_fixture.h"
#include "results/results.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

void write_png(const fs::path& path) {
  OIIO_NAMESPACE::ImageBuf buf(OIIO_NAMESPACE::ImageSpec(8, 8, 3, OIIO_NAMESPACE::TypeDesc::UINT8));
  const float grey[3] = {0.5f, 0.5f, 0.5f};
  OIIO_NAMESPACE::ImageBufAlgo::fill(buf, grey);
  ASSERT_TRUE(buf.write(path.string()));
}

// A run of adapter `adapter` whose tracer image of scene `id` is `image`.
ResultsDocument run_document(const std::string& adapter, const std::string& id,
                             const fs::path& image) {
  ResultsDocument doc;
  doc.suite = "ci";
  RevisionRecord revision;
  revision.role = Role::tracer;
  revision.adapter_name = adapter;
  revision.worktree.sha = std::string(40, 'b');
  doc.revisions.push_back(revision);
  SceneResult scene;
  scene.entry = {id, "tetra", 1, 8, 8};
  scene.status = SceneStatus::measured;
  RunRecord run;
  run.ok = true;
  run.image = image;
  scene.runs.warmup["tracer"] = {run};
  doc.scenes.push_back(scene);
  return doc;
}

TEST(PathsCli, BlessFromRunRefusesASceneIdThatClimbsOut) {
  TempDir dir("raygate-paths");
  write_png(dir.path() / "image.png");
  fs::create_directories(dir.path() / "a" / "b");
  write_results(run_document("mine", "../../escaped", dir.path() / "image.png"),
                dir.path() / "r.json");
  const CliRun r =
      run_raygate({"golden", "bless", "--from-run", "r.json", "--golden-dir", "a/b/g"}, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  // Refused where the document is read (results_check), as every reader of it does.
  EXPECT_NE(r.out.find("r.json: $.scenes[0].scene.id: \"../../escaped\" may hold only"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(dir.path() / "a" / "escaped.png"));
  EXPECT_FALSE(fs::exists(dir.path() / "a" / "b" / "g"));
}

TEST(PathsCli, BlessFromRunRefusesAnImageWithoutAnImageExtension) {
  TempDir dir("raygate-paths");
  write_png(dir.path() / "image.png");
  fs::copy_file(dir.path() / "image.png", dir.path() / "image");
  fs::copy_file(dir.path() / "image.png", dir.path() / "image.json");
  for (const char* image : {"image", "image.json"}) {
    write_results(run_document("mine", "manifest", dir.path() / image), dir.path() / "r.json");
    const CliRun r =
        run_raygate({"golden", "bless", "--from-run", "r.json", "--golden-dir", "g"}, dir);
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find("the tracer image of 'manifest', " + (dir.path() / image).string() +
                         ", has no image file extension"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(dir.path() / "g")) << image;
  }
}

// Without --golden-dir the goldens go to golden/<adapter name>: an absolute name was that path.
TEST(PathsCli, BlessFromRunRefusesAnAdapterNameThatIsAPath) {
  TempDir dir("raygate-paths");
  write_png(dir.path() / "image.png");
  const fs::path escaped = dir.path() / "escaped";
  write_results(run_document(escaped.string(), "tetra", dir.path() / "image.png"),
                dir.path() / "r.json");
  const CliRun r = run_raygate({"golden", "bless", "--from-run", "r.json"}, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("r.json: $.revisions[0].adapter.name: \"" + escaped.string() + "\""),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(escaped));
}

// `raygate run` loads the suite before it measures: a name or id that climbs out of the cache
// stops it there, before any scene file or run folder is made.
TEST(PathsCli, RunRefusesSuiteNamesAndIdsThatClimbOutOfTheCache) {
  TempDir dir("raygate-paths");
  fs::create_directories(dir.path() / "tree");
  const fs::path outside = dir.path() / "outside";
  write_file_atomically(dir.path() / "named.json", R"({"name": ")" + outside.string() +
                                                       R"(", "scenes": [{"scene": "balls"}]})");
  write_file_atomically(dir.path() / "ids.json",
                        R"({"scenes": [{"scene": "balls", "id": "../../../escaped"}]})");
  for (const char* suite : {"named.json", "ids.json"}) {
    const CliRun r = run_raygate({"run", "--adapter", "make-nff", "--worktree", "tree", "--suite",
                                  suite, "--no-store", "--cache-dir", "cache"},
                                 dir);
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find(std::string(suite) + ": $."), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("may hold only letters"), std::string::npos) << r.out;
  }
  EXPECT_FALSE(fs::exists(outside));
  EXPECT_FALSE(fs::exists(dir.path() / "cache" / "scenes"));
}

// A document's short sha names the exported file: one with a crafted short sha would have been
// written outside -o's directory. It is refused on import now (a sweep: it was stored, and then
// blocked the export of the whole store); export's own check (ExportDocuments) stays for stores
// written before.
TEST(PathsCli, ImportRefusesAShortShaThatIsNotTheStartOfTheSha) {
  TempDir dir("raygate-paths");
  DocumentSpec spec;
  spec.sha = fake_sha(1);
  spec.scenes = {{.id = "balls"}};
  ResultsDocument doc = make_document(spec);
  doc.revisions[0].worktree.short_sha = "x/../../escaped";
  write_results(doc, dir.path() / "r.json");
  const CliRun r = run_raygate({"import", "--store", "store.db", "r.json"}, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("short_sha: \"x/../../escaped\" is not the start of sha"), std::string::npos)
      << r.out;
  EXPECT_EQ(run_raygate({"report", "r.json"}, dir).exit_code, 2);
}

// Sweep 17: a working directory deleted under the shell gave the library's "cannot make
// absolute path", exit 3; a TMPDIR that takes no folder (/proc) exit 3, where a missing one is 2.
// Both are the user's to change: exit 2, said in words.
TEST(PathsCli, ADeletedWorkingDirectoryAndAnUnusableTmpdirAreTheUsers) {
  TempDir dir;
  ProcessSpec spec = raygate_spec({}, dir);
  spec.argv = {"sh", "-c", "mkdir gone && cd gone && rmdir ../gone && exec \"$0\" gate r.json",
               RAYGATE_EXE};
  const ProcessResult gone = run_process(spec);
  const std::string said = read_file(spec.stdout_path);
  EXPECT_EQ(gone.exit_code, 2) << said;
  EXPECT_NE(said.find("the working directory no longer exists"), std::string::npos) << said;

  const CliStreams tmp =
      run_raygate_streams({"doctor", "--rounds", "2"}, dir, {{"TMPDIR", "/proc"}});
  EXPECT_EQ(tmp.exit_code, 2) << tmp.err;
  EXPECT_NE(tmp.err.find("TMPDIR=/proc: cannot create a temporary folder in /proc"),
            std::string::npos)
      << tmp.err;
}

}  // namespace
}  // namespace raygate::test
