// Writing an Image through OpenImageIO, the format chosen by the file extension. Float
// formats (EXR, HDR, TIFF, PFM) get the floats as they are; every other format gets 8 bits
// per channel: clamp to [0, 1], then round(v * 255). No current time is written (EXR and TIFF
// get a fixed DateTime), so the same image gives the same bytes on every run.
#pragma once

#include <string>

#include "image/image.h"

namespace raygate {

// Empty if OpenImageIO can write `path`'s format, else why not (unknown extension).
std::string check_output_format(const std::string& path);

// Writes the image; on failure returns false and puts the reason (naming the path) in `error`.
bool write_image(const std::string& path, const Image& image, std::string& error);

// The 8-bit value written for a channel value (NaN counts as 0).
unsigned char to_8bit(float value);

}  // namespace raygate
