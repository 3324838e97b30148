// The baseline's own image encoders: an Image to the bytes of a PNG, PPM, PFM or TGA file.
// The baseline links no image library but zlib, so that its process starts in milliseconds
// and a process-timed run of it measures ray tracing, not the dynamic loader (DESIGN.md §11).
// 8-bit formats get clamp(v, 0, 1) * 255 rounded (to_8bit); PFM gets the floats as they are.
// Every encoder is a pure function: the same image gives the same bytes, with no date in them.
#pragma once

#include <string>

#include "image/image.h"

namespace raygate {

// The 8-bit value written for a channel value (NaN counts as 0).
unsigned char to_8bit(float value);

// Binary PPM (P6), maxval 255, rows from the top.
std::string encode_ppm(const Image& image);

// Portable float map ("PF", 3 channels), little-endian (scale -1), rows from the bottom as the
// format says, values unclamped.
std::string encode_pfm(const Image& image);

// Uncompressed true-colour TGA (type 2, 24 bits, BGR, top-left origin). Throws
// std::length_error for an image wider or taller than 65535 pixels.
std::string encode_tga(const Image& image);

// 8-bit RGB PNG, zlib-compressed, each row with the filter that leaves the smallest residuals.
std::string encode_png(const Image& image);

}  // namespace raygate
