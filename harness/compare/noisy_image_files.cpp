#include "compare/noisy_image_files.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <fmt/core.h>

#include <stdexcept>

#include "compare/image_file.h"
#include "core/error.h"

namespace raygate {

namespace {

namespace OIIO = OIIO_NAMESPACE;

RgbImage from_values(int width, int height, const std::vector<float>& values) {
  return {width, height, values};
}

// A variance file as bless writes it: three channels of floating point. One channel would be
// read as the same variance for red, green and blue, and 8 or 16-bit integers round a pixel's
// small variance to 0 (then every render differs) or clamp a large one at 1: either judges
// against noise that was never measured. "" when it is one, or cannot be opened (the read says
// why).
std::string variance_format_problem(const std::filesystem::path& path) {
  const auto input = OIIO::ImageInput::open(path.string());
  if (!input) return "";
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.nchannels < 3) {
    return fmt::format("{} has {} channel{}: a variance has one per colour (red, green, blue)",
                       path.string(), spec.nchannels, spec.nchannels == 1 ? "" : "s");
  }
  if (!spec.format.is_floating_point()) {
    return fmt::format(
        "{} stores {}-bit whole numbers: a variance is kept in floating point (bless writes "
        "OpenEXR), where small variances do not round to 0",
        path.string(), 8 * spec.format.size());
  }
  return "";
}

}  // namespace

const std::vector<int>& default_tile_sides() {
  static const std::vector<int> sides{8, 32, 128};
  return sides;
}

RgbImage read_rgb_image(const std::filesystem::path& path) {
  OIIO::ImageBuf buf = current_image(path);
  if (std::string problem = oversized_image(buf, path); !problem.empty()) throw UsageError(problem);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
    throw UsageError(path.string() + ": cannot read image: " + buf.geterror());
  }
  const int channels = buf.nchannels();
  const int map[3] = {0, channels > 1 ? 1 : 0, channels > 2 ? 2 : 0};
  const OIIO::ImageBuf rgb = OIIO::ImageBufAlgo::channels(buf, 3, map);
  RgbImage image;
  image.width = rgb.spec().width;
  image.height = rgb.spec().height;
  image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
  if (!rgb.get_pixels(rgb.roi(), OIIO::TypeDesc::FLOAT, image.rgb.data())) {
    throw UsageError(path.string() + ": cannot read pixels: " + rgb.geterror());
  }
  return image;
}

NoisyImageStats stats_of_images(const std::vector<std::filesystem::path>& images) {
  if (images.empty()) throw std::logic_error("stats_of_images: no images");
  const RgbImage first = read_rgb_image(images.front());
  NoisyStatsBuilder builder(first.width, first.height, default_tile_sides());
  builder.add(first);
  for (std::size_t i = 1; i < images.size(); ++i) {
    try {
      builder.add(read_rgb_image(images[i]));
    } catch (const std::invalid_argument& e) {
      throw UsageError(images[i].string() + ": " + e.what());
    }
  }
  return builder.finish();
}

void write_rgb_image(const RgbImage& image, const std::filesystem::path& path) {
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buf(spec);
  buf.set_pixels(buf.roi(), OIIO::TypeDesc::FLOAT, image.rgb.data());
  const bool eight_bit = path.extension() == ".png";
  if (!buf.write(path.string(), eight_bit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT)) {
    throw InfraError("cannot write " + path.string() + ": " + buf.geterror());
  }
}

void write_stats_images(const NoisyImageStats& stats, const std::filesystem::path& mean_file,
                        const std::filesystem::path& variance_file) {
  write_rgb_image(from_values(stats.width, stats.height, stats.mean), mean_file);
  write_rgb_image(from_values(stats.width, stats.height, stats.variance), variance_file);
}

NoisyImageStats read_stats_images(const std::filesystem::path& mean_file,
                                  const std::filesystem::path& variance_file, int runs,
                                  std::vector<ScaleInflation> inflation) {
  const RgbImage mean = read_rgb_image(mean_file);
  const RgbImage variance = read_rgb_image(variance_file);
  if (const std::string problem = variance_format_problem(variance_file); !problem.empty()) {
    throw UsageError(problem + "; bless the golden again");
  }
  if (mean.width != variance.width || mean.height != variance.height) {
    // Either may be the one changed: both sizes said, neither blamed.
    throw UsageError(fmt::format(
        "{} is {}x{} and {} is {}x{}: a golden's mean and variance are of one render; bless "
        "them again",
        mean_file.string(), mean.width, mean.height, variance_file.string(), variance.width,
        variance.height));
  }
  return {mean.width, mean.height, runs, mean.rgb, variance.rgb, std::move(inflation)};
}

}  // namespace raygate
