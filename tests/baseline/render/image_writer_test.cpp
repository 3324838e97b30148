// Image output through OpenImageIO: 8-bit quantization, float EXR, byte-identical reruns.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
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

Image gradient(int width, int height) {
  Image image(width, height);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      image.set(i, j, {i / double(width - 1), j / double(height - 1), 1.5});
    }
  }
  return image;
}

TEST(ImageWriter, QuantizesWithClampAndRounding) {
  EXPECT_EQ(to_8bit(0.0f), 0);
  EXPECT_EQ(to_8bit(-3.0f), 0);
  EXPECT_EQ(to_8bit(1.0f), 255);
  EXPECT_EQ(to_8bit(7.0f), 255);
  EXPECT_EQ(to_8bit(0.5f), 128);  // 127.5 rounds up
  EXPECT_EQ(to_8bit(std::nanf("")), 0);
}

// EXR and TIFF writers stamp the current time unless given one; none may leak through.
TEST(ImageWriter, EveryFormatIsByteIdenticalAcrossRuns) {
  const Image image = gradient(17, 9);
  const std::vector<std::string> extensions = {"png", "exr", "ppm", "tga", "tif"};
  std::string error;
  for (const std::string& ext : extensions) {
    ASSERT_TRUE(write_image((temp_dir() / ("a." + ext)).string(), image, error)) << error;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // a timestamp would differ
  for (const std::string& ext : extensions) {
    ASSERT_TRUE(write_image((temp_dir() / ("b." + ext)).string(), image, error)) << error;
    EXPECT_EQ(read_bytes(temp_dir() / ("a." + ext)), read_bytes(temp_dir() / ("b." + ext)))
        << ext;
  }
}

TEST(ImageWriter, ExrKeepsFloatsUnclamped) {
  const Image image = gradient(5, 4);
  std::string error;
  const fs::path path = temp_dir() / "g.exr";
  ASSERT_TRUE(write_image(path.string(), image, error)) << error;
  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 5);
  EXPECT_EQ(in->spec().height, 4);
  std::vector<float> pixels(5 * 4 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data()));
  EXPECT_EQ(pixels, image.rgb);
}

TEST(ImageWriter, PngHoldsTheQuantizedValues) {
  const Image image = gradient(5, 4);
  std::string error;
  const fs::path path = temp_dir() / "g.png";
  ASSERT_TRUE(write_image(path.string(), image, error)) << error;
  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in);
  std::vector<unsigned char> pixels(5 * 4 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
  for (std::size_t i = 0; i < pixels.size(); ++i) EXPECT_EQ(pixels[i], to_8bit(image.rgb[i]));
}

TEST(ImageWriter, ReportsUnwritablePathsAndUnknownFormats) {
  std::string error;
  EXPECT_FALSE(write_image("/nonexistent-dir/x.png", gradient(2, 2), error));
  EXPECT_NE(error.find("/nonexistent-dir/x.png"), std::string::npos);
  EXPECT_FALSE(check_output_format("image.nosuchformat").empty());
  EXPECT_FALSE(check_output_format("noextension").empty());
  EXPECT_TRUE(check_output_format("x.png").empty());
  EXPECT_TRUE(check_output_format("x.exr").empty());
}

}  // namespace
}  // namespace raygate
