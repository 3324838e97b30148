// The baseline's own image encoders (PNG, PPM, PFM, TGA): every file decodes, through
// OpenImageIO as the harness reads it, to exactly the pixels written (8-bit: to_8bit of each
// value; PFM: the floats, unclamped), the right way up; the same image gives the same bytes;
// formats it does not write are refused with a way out.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

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
      image.set(i, j, {i / double(width - 1) * 1.2 - 0.1, j % 3 == 0 ? noise : j / double(height),
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

TEST(ImageWriter, TgaRefusesImagesBeyondItsSizeField) {
  std::string error;
  EXPECT_FALSE(write_image((temp_dir() / "wide.tga").string(), Image(70000, 1), error));
  EXPECT_NE(error.find("65535"), std::string::npos) << error;
}

}  // namespace
}  // namespace raygate
