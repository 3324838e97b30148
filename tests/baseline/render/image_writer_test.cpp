// The baseline's own image encoders (PNG, PPM, PFM, TGA): every file decodes, through
// OpenImageIO as the harness reads it, to exactly the pixels written (8-bit: to_8bit of each
// value; PFM: the floats, unclamped), the right way up; the same image gives the same bytes;
// formats it does not write are refused with a way out; a write that fails midway (a full
// disk) leaves the old image whole and no temporary beside it.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <OpenImageIO/imageio.h>
#include <zlib.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "image/file_output.h"
#include "image/image_writer.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

// One directory per test: CTest runs the tests as parallel processes.
fs::path temp_dir() {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const fs::path dir = fs::path(RAYGATE_BINARY_DIR) / "test-tmp" / "image_writer" / test;
  fs::create_directories(dir);
  return dir;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Not square and not symmetric, so a transposed or flipped file shows; values below 0 and above
// 1 for the clamping; a hash-like pattern in green so that every PNG row filter gets chosen.
Image test_image(int width, int height) {
  Image image(width, height);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double noise = double((i * 7919 + j * 104729) % 251) / 250.0;
      image.set(i, j,
                {i / double(width - 1) * 1.2 - 0.1, j % 3 == 0 ? noise : j / double(height),
                 1.5 - 0.25 * i});
    }
  }
  return image;
}

fs::path write(const std::string& name, const Image& image) {
  const fs::path path = temp_dir() / name;
  std::string error;
  EXPECT_TRUE(write_image(path.string(), image, error)) << error;
  return path;
}

struct Decoded {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> pixels;  // as OpenImageIO converts them to float
};

Decoded decode(const fs::path& path, OIIO::TypeDesc as) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    ADD_FAILURE() << path << ": " << OIIO::geterror();
    return {};
  }
  const OIIO::ImageSpec& spec = in->spec();
  Decoded d{spec.width, spec.height, spec.nchannels, {}};
  if (as == OIIO::TypeDesc::UINT8) {
    std::vector<unsigned char> bytes(std::size_t(d.width) * std::size_t(d.height) * 3);
    EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data())) << in->geterror();
    d.pixels.assign(bytes.begin(), bytes.end());
  } else {
    d.pixels.resize(std::size_t(d.width) * std::size_t(d.height) * 3);
    EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, d.pixels.data()))
        << in->geterror();
  }
  return d;
}

std::vector<float> quantized(const Image& image) {
  std::vector<float> out;
  for (const float v : image.rgb) out.push_back(to_8bit(v));
  return out;
}

TEST(ImageWriter, QuantizesWithClampAndRounding) {
  EXPECT_EQ(to_8bit(0.0f), 0);
  EXPECT_EQ(to_8bit(-3.0f), 0);
  EXPECT_EQ(to_8bit(1.0f), 255);
  EXPECT_EQ(to_8bit(7.0f), 255);
  EXPECT_EQ(to_8bit(0.5f), 128);  // 127.5 rounds up
  EXPECT_EQ(to_8bit(std::nanf("")), 0);
}

TEST(ImageWriter, EightBitFormatsDecodeToTheQuantizedPixels) {
  const Image image = test_image(37, 23);
  for (const std::string ext : {"png", "ppm", "tga", "PNG"}) {
    const Decoded d = decode(write("g." + ext, image), OIIO::TypeDesc::UINT8);
    EXPECT_EQ(d.width, 37) << ext;
    EXPECT_EQ(d.height, 23) << ext;
    EXPECT_EQ(d.channels, 3) << ext;
    EXPECT_EQ(d.pixels, quantized(image)) << ext;
  }
}

TEST(ImageWriter, PfmKeepsFloatsUnclampedAndTheRightWayUp) {
  const Image image = test_image(9, 6);
  const Decoded d = decode(write("g.pfm", image), OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(d.width, 9);
  EXPECT_EQ(d.height, 6);
  EXPECT_EQ(d.channels, 3);
  EXPECT_EQ(d.pixels, image.rgb);
}

// A large flat image compresses: the PNG really is deflated, not stored.
TEST(ImageWriter, PngIsCompressed) {
  Image flat(256, 256);
  for (float& v : flat.rgb) v = 0.25f;
  const fs::path path = write("flat.png", flat);
  EXPECT_LT(fs::file_size(path), 2000u);
  EXPECT_EQ(decode(path, OIIO::TypeDesc::UINT8).pixels, quantized(flat));
}

// Byte rows that PNG's predictors fit exactly, in bands that each start from a row of noise: a
// band repeating the row above (Up), one whose pixels average their left and upper neighbours
// (Average), one of Paeth predictions. Each band makes its filter the cheapest, so every filter
// of the encoder is exercised (noise rows take None or Sub).
Image filter_bands(int width) {
  std::mt19937 random(7);
  const int band = 6;
  const int height = 4 * band;
  const int stride = width * 3;
  std::vector<int> v(std::size_t(stride) * std::size_t(height));
  auto at = [&](int x, int y) -> int& { return v[std::size_t(y * stride + x)]; };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < stride; ++x) {
      const int a = x >= 3 ? at(x - 3, y) : 0;
      const int b = y > 0 ? at(x, y - 1) : 0;
      const int c = x >= 3 && y > 0 ? at(x - 3, y - 1) : 0;
      const int p = a + b - c;
      const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
      const int paeth = pa <= pb && pa <= pc ? a : (pb <= pc ? b : c);
      const int kind = y / band;  // 0 noise, 1 up, 2 average, 3 Paeth
      const bool noise = kind == 0 || y % band == 0 || (kind >= 2 && x < 3);
      at(x, y) = noise ? int(random() % 256) : kind == 1 ? b : kind == 2 ? (a + b) / 2 : paeth;
    }
  }
  Image image(width, height);
  for (std::size_t i = 0; i < v.size(); ++i) image.rgb[i] = float(v[i]) / 255.0f;
  return image;
}

// The filter type byte of each row of a PNG written by encode_png (one IDAT chunk).
std::set<int> row_filters(const std::string& png, int width, int height) {
  const std::size_t idat = png.find("IDAT");
  const auto* p = reinterpret_cast<const unsigned char*>(png.data() + idat - 4);
  const uLong length = (uLong(p[0]) << 24) | (uLong(p[1]) << 16) | (uLong(p[2]) << 8) | p[3];
  const std::size_t stride = std::size_t(width) * 3 + 1;
  std::vector<unsigned char> raw(stride * std::size_t(height));
  uLongf size = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &size, p + 8, length), Z_OK);
  std::set<int> filters;
  for (int y = 0; y < height; ++y) filters.insert(raw[std::size_t(y) * stride]);
  return filters;
}

TEST(ImageWriter, PngUsesEveryRowFilterAndDecodesExactly) {
  const Image image = filter_bands(40);
  EXPECT_EQ(row_filters(encode_png(image), image.width, image.height),
            (std::set<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(decode(write("bands.png", image), OIIO::TypeDesc::UINT8).pixels, quantized(image));
}

TEST(ImageWriter, EveryFormatIsByteIdenticalAcrossRuns) {
  const Image image = test_image(17, 9);
  for (const std::string ext : {"png", "ppm", "pfm", "tga"}) {
    EXPECT_EQ(read_bytes(write("a." + ext, image)), read_bytes(write("b." + ext, image))) << ext;
  }
}

TEST(ImageWriter, OneByOnePixelImages) {
  Image one(1, 1);
  one.set(0, 0, {0.2, 0.4, 0.6});
  for (const std::string ext : {"png", "ppm", "tga"}) {
    EXPECT_EQ(decode(write("one." + ext, one), OIIO::TypeDesc::UINT8).pixels, quantized(one))
        << ext;
  }
  EXPECT_EQ(decode(write("one.pfm", one), OIIO::TypeDesc::FLOAT).pixels, one.rgb);
}

TEST(ImageWriter, ReportsUnwritablePathsAndUnknownFormats) {
  std::string error;
  EXPECT_FALSE(write_image("/nonexistent-dir/x.png", test_image(2, 2), error));
  EXPECT_NE(error.find("/nonexistent-dir/x.png"), std::string::npos) << error;
  EXPECT_FALSE(write_image((temp_dir() / "x.exr").string(), test_image(2, 2), error));
  EXPECT_FALSE(fs::exists(temp_dir() / "x.exr"));
  EXPECT_FALSE(check_output_format("noextension").empty());
  EXPECT_FALSE(check_output_format("dir.png/noextension").empty());
  for (const char* ok : {"x.png", "x.ppm", "x.pfm", "x.tga", "X.PFM"}) {
    EXPECT_TRUE(check_output_format(ok).empty()) << ok;
  }
  // EXR and TIFF: the message says how to get one.
  const std::string exr = check_output_format("render.exr");
  EXPECT_NE(exr.find(".pfm"), std::string::npos) << exr;
  EXPECT_NE(exr.find("oiiotool x.pfm -o x.exr"), std::string::npos) << exr;
}

TEST(ImageWriter, AWriteFailingMidwayKeepsTheOldImageWhole) {
  // A file-size limit makes write() fail part way (EFBIG), as a full disk does (ENOSPC).
  const fs::path path = write("keep.pfm", test_image(4, 4));
  const std::string old_bytes = read_bytes(path);
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = saved;
  small.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string error;
  const bool written = write_image(path.string(), test_image(200, 200), error);  // 480 KB
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previous);
  EXPECT_FALSE(written);
  EXPECT_NE(error.find(path.string()), std::string::npos) << error;
  EXPECT_NE(error.find(std::strerror(EFBIG)), std::string::npos) << error;
  EXPECT_EQ(read_bytes(path), old_bytes);
  for (const auto& entry : fs::directory_iterator(temp_dir())) {
    EXPECT_EQ(entry.path().filename(), "keep.pfm") << "left behind: " << entry.path();
  }
}

TEST(ImageWriter, ADeviceIsWrittenThroughNeverReplaced) {
  std::string error;
  // The format comes from the extension, so a device is reached through the file writer.
  EXPECT_TRUE(write_file_replacing("/dev/null", "P3\n1 1\n255\n0 0 0\n", error)) << error;
  struct stat node {};
  ASSERT_EQ(::stat("/dev/null", &node), 0);
  EXPECT_TRUE(S_ISCHR(node.st_mode));
  fs::create_directories(temp_dir() / "folder.png");
  EXPECT_FALSE(write_image((temp_dir() / "folder.png").string(), test_image(2, 2), error));
  EXPECT_NE(error.find("is a directory"), std::string::npos) << error;
}

TEST(ImageWriter, TgaRefusesImagesBeyondItsSizeField) {
  std::string error;
  EXPECT_FALSE(write_image((temp_dir() / "wide.tga").string(), Image(70000, 1), error));
  EXPECT_NE(error.find("65535"), std::string::npos) << error;
}

}  // namespace
}  // namespace raygate
