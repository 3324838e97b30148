// Writing an Image to a file, the format chosen by the file extension (case-insensitive):
// .png, .ppm and .tga get 8 bits per channel (clamped, rounded), .pfm gets the floats as they
// are. Encoded by the baseline itself (image/encoders.h), no image library: see there for why.
// No date is written, so the same image gives the same bytes on every run.
#pragma once

#include <string>

#include "image/encoders.h"
#include "image/image.h"

namespace raygate {

// Empty if `path`'s extension names a format the baseline writes, else why not: what it
// writes, and how to get the others.
std::string check_output_format(const std::string& path);

// Writes the image, replacing any old file whole (image/file_output.h); on failure returns false,
// leaves an old file as it was, and puts the reason (naming the path) in `error`.
bool write_image(const std::string& path, const Image& image, std::string& error);

}  // namespace raygate
