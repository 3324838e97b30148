#include "pipeline_fixture.h"

#include <fstream>

#include "core/paths.h"

namespace raygate::testing {

namespace fs = std::filesystem;

namespace {

// Two scenes small enough to generate in milliseconds.
constexpr const char* kSuite = R"({
  "name": "pipeline-test",
  "description": "the pipeline's in-process tests: two small scenes",
  "scenes": [
    {"id": "tetra", "scene": "tetra", "size": 1, "resolution": [8, 8]},
    {"id": "balls", "scene": "balls", "size": 1, "resolution": [8, 8]}
  ]
})";

// The build copies the committed cost beside the tracer, which it makes as an empty file: it is
// never started (the executor is fake), but run and compare check that the run program exists.
constexpr const char* kAdapter = R"({
  "name": "fake-cost-tracer",
  "description": "pipeline tests: a tracer whose time per render is the committed file 'cost'",
  "scene_format": "nff",
  "build": [["cp", "{src}/cost", "{build}/cost"], ["touch", "{build}/tracer"]],
  "run": ["{build}/tracer", "{scene}", "-o", "{workdir}/image.ppm"],
  "image": "{workdir}/image.ppm",
  "timing": {"source": "process", "metric": "wall"},
  "threads": 1,
  "timeout_s": {"build": 60, "run": 60}
})";

// The argument after `flag` in argv, if any.
std::optional<std::string> argument_after(const ProcessSpec& spec, const std::string& flag) {
  for (std::size_t i = 0; i + 1 < spec.argv.size(); ++i) {
    if (spec.argv[i] == flag) return spec.argv[i + 1];
  }
  return std::nullopt;
}

// An 8x8 grey PPM, the suite's resolution: every run renders the same picture, so image checks
// pass.
void write_image(const fs::path& path) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << "P6\n8 8\n255\n";
  for (int i = 0; i < 8 * 8 * 3; ++i) out.put(static_cast<char>(128));
}

// What a real run leaves: the image at -o, and the baseline's --stats file.
void leave_outputs(const ProcessSpec& spec) {
  if (const auto image = argument_after(spec, "-o")) write_image(*image);
  if (const auto stats = argument_after(spec, "--stats")) {
    write_file_atomically(
        *stats, R"({"parse_seconds": 0.1, "prepare_seconds": 0.1, "render_seconds": 0.8})");
  }
}

}  // namespace

std::vector<std::string> RecordingProgress::lines_with(const std::string& part) const {
  std::vector<std::string> found;
  for (const std::string& text : lines) {
    if (text.find(part) != std::string::npos) found.push_back(text);
  }
  return found;
}

PipelineTest::PipelineTest()
    : repo_(dir_.path() / "tracer-repo"), baseline_(locate_tools().baseline) {
  const fs::path suite = dir_.path() / "suite.json";
  write_file_atomically(suite, kSuite);
  fs::create_directories(dir_.path() / "no-goldens");
  context_.tools = locate_tools();
  context_.adapter = parse_adapter(kAdapter, "pipeline_fixture adapter");
  context_.suite = load_suite(suite.string(), context_.tools.data_root);
  context_.scenes = select_scenes(context_.suite, {});
  context_.cache_dir = dir_.path() / ".raygate";
  context_.golden_dir = dir_.path() / "no-goldens";
  context_.jobs = 1;
  // A file stands in for /dev/cpu_dma_latency: the tests change no idle state of the machine,
  // and their documents say "poll" whoever runs them.
  context_.idle_poll_device = dir_.path() / "cpu_dma_latency";
  write_file_atomically(context_.idle_poll_device, "");
  executor_.time_by([this](const ProcessSpec& spec) { return seconds_of(spec); });
  executor_.on_success(leave_outputs);
}

std::string PipelineTest::commit_tracer(const std::string& cost, const std::string& message) {
  if (cost.empty()) {
    if (fs::exists(repo_.path() / "cost")) repo_.remove("cost");
  } else {
    repo_.write("cost", cost + "\n");
  }
  repo_.write("README", message + "\n");  // every commit changes something
  return repo_.commit(message);
}

std::optional<double> PipelineTest::seconds_of(const ProcessSpec& spec) {
  const fs::path program = spec.argv.at(0);
  if (program.filename() != "tracer") return 1.0;  // the baseline
  double seconds = std::stod(read_file(program.parent_path() / "cost"));
  if (!noise_.empty()) seconds *= noise_[tracer_runs_ % noise_.size()];
  ++tracer_runs_;
  return seconds;
}

}  // namespace raygate::testing
