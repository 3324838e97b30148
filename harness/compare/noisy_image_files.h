// Files for the Monte Carlo image check: a run's image read as linear float RGB, the statistics
// of several runs' images, and a golden's statistics stored as two float images (per pixel mean
// and variance, OpenEXR) that the golden manifest names with the runs they summarise.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "compare/noisy_stats.h"

namespace raygate {

// The tile sides whose inflation is measured and tested (docs/monte-carlo-images.md).
const std::vector<int>& default_tile_sides();

// Throws UsageError naming the file when it cannot be read. Grey is widened to RGB, alpha dropped.
RgbImage read_rgb_image(const std::filesystem::path& path);

// Throws UsageError naming the first image that cannot be read or differs in size.
NoisyImageStats stats_of_images(const std::vector<std::filesystem::path>& images);

// Writes the mean and the variance as float images; throws InfraError when it cannot.
void write_stats_images(const NoisyImageStats& stats, const std::filesystem::path& mean_file,
                        const std::filesystem::path& variance_file);

// The statistics back from the two images and what the manifest holds about them.
NoisyImageStats read_stats_images(const std::filesystem::path& mean_file,
                                  const std::filesystem::path& variance_file, int runs,
                                  std::vector<ScaleInflation> inflation);

// Writes an RGB float image (any format OpenImageIO writes, by extension; 8-bit for .png).
void write_rgb_image(const RgbImage& image, const std::filesystem::path& path);

}  // namespace raygate
