#include "compare/image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "compare/image_file.h"
#include "core/error.h"

namespace raygate {
namespace {

namespace OIIO = OIIO_NAMESPACE;

// The first non-empty line of a library's message, without trailing blanks, at most 200 bytes.
std::string first_line(const std::string& text) {
  std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start == std::string::npos) return "unknown error";
  const std::size_t end = text.find_first_of("\r\n", start);
  std::string line = text.substr(start, end == std::string::npos ? end : end - start);
  line.erase(line.find_last_not_of(" \t") + 1);
  if (line.size() > 200) line = line.substr(0, 197) + "...";
  return line;
}

OIIO::ImageBuf load_rgb(const std::filesystem::path& path) {
  OIIO::ImageBuf buf = current_image(path);
  if (std::string problem = oversized_image(buf, path); !problem.empty()) throw UsageError(problem);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
    throw UsageError(path.string() + ": cannot read image: " + first_line(buf.geterror()));
  }
  const int channels = buf.nchannels();
  if (channels == 3) return buf;
  // Grey images are widened to RGB, and alpha (or anything past blue) is dropped.
  const int map[3] = {0, channels > 1 ? 1 : 0, channels > 2 ? 2 : 0};
  OIIO::ImageBuf rgb = OIIO::ImageBufAlgo::channels(buf, 3, map);
  if (rgb.has_error()) throw UsageError(path.string() + ": " + rgb.geterror());
  return rgb;
}

double mean_luminance(const OIIO::ImageBuf& buf) {
  const auto stats = OIIO::ImageBufAlgo::computePixelStats(buf);
  if (stats.avg.size() < 3) return 0.0;
  return 0.2126 * stats.avg[0] + 0.7152 * stats.avg[1] + 0.0722 * stats.avg[2];
}

long count_nonfinite(const OIIO::ImageBuf& buf) {
  const auto stats = OIIO::ImageBufAlgo::computePixelStats(buf);
  long total = 0;
  for (std::size_t c = 0; c < stats.nancount.size(); ++c) {
    total += static_cast<long>(stats.nancount[c] + stats.infcount[c]);
  }
  return total;
}

struct NonFinite {
  long pixels = 0;
  int x = 0, y = 0;  // the first, in reading order
};

NonFinite nonfinite_pixels(const OIIO::ImageBuf& rgb) {
  NonFinite found;
  for (OIIO::ImageBuf::ConstIterator<float> it(rgb); !it.done(); ++it) {
    if (std::isfinite(it[0]) && std::isfinite(it[1]) && std::isfinite(it[2])) continue;
    if (found.pixels++ == 0) {
      found.x = it.x();
      found.y = it.y();
    }
  }
  return found;
}

}  // namespace

std::string unreadable_image(const std::filesystem::path& image) {
  OIIO::ImageBuf buf = current_image(image);
  if (std::string problem = oversized_image(buf, image); !problem.empty()) return problem;
  if (buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) return {};
  return image.string() + ": cannot read image: " + first_line(buf.geterror());
}

ImageMetrics compare_images(const std::filesystem::path& actual,
                            const std::filesystem::path& expected,
                            const ImageThresholds& thresholds) {
  const OIIO::ImageBuf a = load_rgb(actual);
  const OIIO::ImageBuf b = load_rgb(expected);
  ImageMetrics m;
  m.width = a.spec().width;
  m.height = a.spec().height;
  m.expected_width = b.spec().width;
  m.expected_height = b.spec().height;
  m.nonfinite_values = count_nonfinite(a);
  const NonFinite broken = nonfinite_pixels(a);
  m.nonfinite_pixels = broken.pixels;
  m.nonfinite_x = broken.x;
  m.nonfinite_y = broken.y;
  m.expected_nonfinite_pixels = nonfinite_pixels(b).pixels;
  m.mean_luminance_actual = mean_luminance(a);
  m.mean_luminance_expected = mean_luminance(b);
  if (m.width != m.expected_width || m.height != m.expected_height) {
    m.size_mismatch = true;
    m.max_error = std::numeric_limits<double>::infinity();
    m.percent_over_fail = 100.0;
    return m;
  }
  const auto r = OIIO::ImageBufAlgo::compare(a, b, static_cast<float>(thresholds.fail_threshold),
                                             static_cast<float>(thresholds.warn_threshold));
  m.mean_error = r.meanerror;
  m.rms_error = r.rms_error;
  m.psnr_db = r.PSNR;
  m.max_error = r.maxerror;
  m.max_x = r.maxx;
  m.max_y = r.maxy;
  m.max_channel = r.maxc;
  m.pixels_over_warn = static_cast<long>(r.nwarn);
  m.pixels_over_fail = static_cast<long>(r.nfail);
  const double pixels = static_cast<double>(m.width) * m.height;
  m.percent_over_fail = pixels > 0 ? 100.0 * static_cast<double>(m.pixels_over_fail) / pixels : 0;
  if (r.maxerror > 0) {
    float va[3];
    float vb[3];
    a.getpixel(m.max_x, m.max_y, va, 3);
    b.getpixel(m.max_x, m.max_y, vb, 3);
    m.max_actual_value = va[m.max_channel];
    m.max_expected_value = vb[m.max_channel];
  }
  return m;
}

ImageVerdict judge(const ImageMetrics& m, const ImageThresholds& t) {
  if (m.size_mismatch || m.nonfinite_values > 0 || m.nonfinite_pixels > 0) {
    return ImageVerdict::fail;
  }
  if (m.max_error > t.hard_fail) return ImageVerdict::fail;
  if (m.percent_over_fail > t.fail_percent) return ImageVerdict::fail;
  if (m.pixels_over_warn > 0) return ImageVerdict::warn;
  return ImageVerdict::pass;
}

std::string summarize(const ImageMetrics& m) {
  if (m.size_mismatch) {
    return fmt::format("size {}x{} but expected {}x{}", m.width, m.height, m.expected_width,
                       m.expected_height);
  }
  if (m.identical()) return "identical";
  if (m.nonfinite_pixels > 0) {
    // The error statistics of an image with NaN in it are NaN or meaningless: say what is wrong.
    return fmt::format("{} NaN/Inf pixels of {}, first at ({},{})", m.nonfinite_pixels,
                       static_cast<long>(m.width) * m.height, m.nonfinite_x, m.nonfinite_y);
  }
  std::string text = fmt::format(
      "max {:.4g} at ({},{}) ch {}: {:.4g} vs {:.4g}; {:.3g}% pixels over threshold; "
      "RMS {:.3g}; PSNR {:.1f} dB",
      m.max_error, m.max_x, m.max_y, m.max_channel, m.max_actual_value, m.max_expected_value,
      m.percent_over_fail, m.rms_error, m.psnr_db);
  if (m.nonfinite_values > 0) text += fmt::format("; {} NaN/Inf values", m.nonfinite_values);
  return text;
}

void write_evidence(const std::filesystem::path& actual, const std::filesystem::path& expected,
                    const std::filesystem::path& dir, const std::string& stem) {
  std::filesystem::create_directories(dir);
  const OIIO::ImageBuf a = load_rgb(actual);
  const OIIO::ImageBuf b = load_rgb(expected);
  auto save = [&](const OIIO::ImageBuf& buf, const std::string& suffix) {
    const std::filesystem::path out = dir / (stem + suffix);
    if (!buf.write(out.string(), OIIO::TypeDesc::UINT8)) {
      throw InfraError("cannot write " + out.string() + ": " + buf.geterror());
    }
  };
  save(a, ".actual.png");
  save(b, ".expected.png");
  if (a.spec().width == b.spec().width && a.spec().height == b.spec().height) {
    OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(a, b);
    diff = OIIO::ImageBufAlgo::mul(diff, 16.0f);
    save(diff, ".diff.png");
  }
}

}  // namespace raygate
