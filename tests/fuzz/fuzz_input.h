// Shared by the fuzz targets (tests/fuzz/*_target.cpp): the input as text, and a scratch file for
// readers that take a path. A target returns normally for input the reader accepts or refuses
// with its documented error; anything else (another exception, a crash, a hang) is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace raygate::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// `text` written to a file named `name` in a folder of this process's own, replaced each call.
std::filesystem::path scratch_file(std::string_view text, const std::string& name);

}  // namespace raygate::fuzz
