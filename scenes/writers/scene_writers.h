// Scene writers: a parsed NFF scene (baseline/nff/scene.h) written for other ray tracers, so that
// they render the same SPD scene as raygate-baseline. Three formats: POV-Ray 3.7 SDL, Wavefront
// OBJ + MTL, and pbrt-v4. How every NFF primitive and material maps, and what is approximated,
// is in docs/scene-formats.md. Output is deterministic: the same scene gives the same bytes.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "nff/scene.h"

namespace raygate::writers {

enum class OutputFormat { pov, obj, pbrt };

// "pov", "obj" or "pbrt"; nullopt for anything else.
std::optional<OutputFormat> parse_output_format(std::string_view name);
std::string_view format_name(OutputFormat format);

struct WriteOptions {
  // Tessellation of curved primitives where a format has no such primitive (OBJ spheres and
  // cones, pbrt-v4 cones): facets around the axis. Spheres get segments/2 latitude bands.
  int segments = 16;
};

// The stream writers. Each throws std::invalid_argument for a view raygate-baseline rejects
// too (from = at, up parallel to the view, angle outside (0°, 180°), non-positive resolution),
// or segments outside 3..1024. Degenerate primitives (zero radius or area, zero-length cones,
// non-finite coordinates) are skipped, as the baseline drops them, and counted in a comment.
void write_pov(const nff::Scene& scene, std::ostream& out);
// `mtl_name` is the file name the OBJ's `mtllib` line refers to.
void write_obj(const nff::Scene& scene, std::ostream& out, std::string_view mtl_name,
               const WriteOptions& options = {});
void write_mtl(const nff::Scene& scene, std::ostream& out);
// `image_name` is the file name written into the pbrt Film (e.g. "balls.exr").
void write_pbrt(const nff::Scene& scene, std::ostream& out, std::string_view image_name,
                const WriteOptions& options = {});

// Writes the scene to `out` (and, for OBJ, the MTL beside it: `out` with extension ".mtl"),
// each file atomically (a reader never sees half a file). Returns the files written, main file
// first. Throws std::invalid_argument as above and raygate::InfraError when a file cannot be
// written.
std::vector<std::filesystem::path> write_scene_files(const nff::Scene& scene, OutputFormat format,
                                                     const std::filesystem::path& out,
                                                     const WriteOptions& options = {});

}  // namespace raygate::writers
