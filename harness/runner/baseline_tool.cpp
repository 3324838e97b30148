#include "runner/baseline_tool.h"

#include "core/error.h"
#include "core/json_reader.h"
#include "core/fs.h"

namespace raygate {

BaselineTool::BaselineTool(std::filesystem::path executable) : executable_(std::move(executable)) {
  TempDir temp("raygate-version");
  ProcessSpec spec;
  spec.argv = {executable_.string(), "--version"};
  spec.stdout_path = temp.path() / "version.txt";
  spec.timeout = std::chrono::seconds(30);
  const ProcessResult result = run_process(spec);
  if (!result.succeeded()) {
    throw InfraError(executable_.string() + " --version " + result.describe());
  }
  const std::string text = read_file(spec.stdout_path);
  version_line_ = text.substr(0, text.find('\n'));
}

std::string BaselineTool::source_hash() const {
  static constexpr std::string_view kTag = "source-sha256:";
  const auto at = version_line_.find(kTag);
  if (at == std::string::npos) return {};
  const std::string rest = version_line_.substr(at + kTag.size());
  return rest.substr(0, rest.find(' '));
}

BaselineRender BaselineTool::render(const std::filesystem::path& scene,
                                    const std::filesystem::path& image,
                                    const BaselineOptions& options) const {
  BaselineRender out;
  out.image = image;
  out.stats_path = std::filesystem::path(image).replace_extension(".stats.json");
  out.log = std::filesystem::path(image).replace_extension(".log");
  ProcessSpec spec;
  spec.argv = {executable_.string(),   scene.string(),   "-o",
               image.string(),         "--accel",        options.accel,
               "--sampling",           options.sampling, "--stats",
               out.stats_path.string()};
  spec.stdout_path = out.log;
  spec.stderr_path = out.log;
  spec.timeout = options.timeout;
  out.process = run_process(spec);
  if (out.process.succeeded()) {
    try {
      out.stats = nlohmann::json::parse(read_file(out.stats_path));
    } catch (const std::exception& e) {
      throw InfraError(out.stats_path.string() +
                       ": unreadable baseline statistics: " + plain_exception_text(e));
    }
  }
  return out;
}

}  // namespace raygate
