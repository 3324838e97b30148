// sombrero (spd-spec.md §3.11): a damped-cosine "hat" height field, written as NFF triangles
// with the height along y. 1 light.
#include <cmath>
#include <vector>

#include "generators/generators.h"

namespace raygate::scenes {
namespace {

void write_header(NffWriter& out) {
  out.background({0.078, 0.361, 0.753});
  out.view({0.0, 5.0, -8.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 40.0, 0.01, 512, 512);
  out.light({10.0, 10.0, -10.0});
  out.material({{1.0, 0.1, 0.1}, 0.1, 0.8, 0.0, 0.5, 40.0, 0.0, 1.0});
}

// The height samples over [−4, 4 − 8/W]², stored as 32-bit floats as the SPD stores them
// (§3.11, §8 precision caveats); x and y advance by repeated addition.
std::vector<std::vector<float>> sample_heights(int width, int height) {
  std::vector<std::vector<float>> d(height, std::vector<float>(width));
  double y = -4.0;
  for (int i = 0; i < height; ++i) {
    double x = -4.0;
    for (int j = 0; j < width; ++j) {
      const double rho = std::sqrt(x * x + y * y);
      d[i][j] =
          static_cast<float>((3.0 * std::cos(2.0 * 3.14159265358 * rho) * std::exp(-rho)) / 3.0);
      x += 8.0 / width;
    }
    y += 8.0 / height;
  }
  return d;
}

}  // namespace

void generate_sombrero(int size, NffWriter& out) {
  write_header(out);
  const int width = 32 << (size - 1);
  const int height = width;
  const std::vector<std::vector<float>> d = sample_heights(width, height);
  // The mesh spreads the samples over the full [−4, 4] (§3.11 note).
  const double dx = 8.0 / (width - 1);
  const double dz = 8.0 / (height - 1);
  auto vertex = [&](int i, int j) {
    return Vec3{-4.0 + j * dx, -3.0 + static_cast<double>(d[i][j]), -4.0 + i * dz};
  };
  for (int i = 0; i + 1 < height; ++i) {
    for (int j = 0; j + 1 < width; ++j) {
      const Vec3 first[3] = {vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
      const Vec3 second[3] = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)};
      out.polygon(first);
      out.polygon(second);
    }
  }
}

}  // namespace raygate::scenes
