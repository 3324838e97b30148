#include "core/sanitize.h"

#include <fmt/format.h>

#include <cstdint>

#include "core/utf8.h"

namespace raygate {
namespace {

// The code point of the well-formed sequence `bytes` (1 to 4 bytes of valid UTF-8).
std::uint32_t code_point_of(std::string_view bytes) {
  const auto lead = static_cast<unsigned char>(bytes[0]);
  if (bytes.size() == 1) return lead;
  const std::uint32_t lead_bits = bytes.size() == 2 ? 0x1F : bytes.size() == 3 ? 0x0F : 0x07;
  std::uint32_t code = lead & lead_bits;
  for (std::size_t i = 1; i < bytes.size(); ++i) {
    code = (code << 6) | (static_cast<unsigned char>(bytes[i]) & 0x3F);
  }
  return code;
}

// "\x1b" for ASCII, "\u009b" beyond: what a reader can see and search for.
std::string visible_escape(std::uint32_t code) {
  return code < 0x80 ? fmt::format("\\x{:02x}", code) : fmt::format("\\u{:04x}", code);
}

// Copies `text` (repaired to UTF-8), writing each code point `hidden` says yes to as its escape.
template <typename Hidden>
std::string escaped_where(std::string_view text, Hidden hidden) {
  const std::string valid = repaired_utf8(text);
  std::string out;
  out.reserve(valid.size());
  std::string_view rest = valid;
  while (!rest.empty()) {
    const std::size_t length = utf8_sequence_length(rest);  // >= 1: the text is valid
    const std::string_view bytes = rest.substr(0, length);
    const std::uint32_t code = code_point_of(bytes);
    if (hidden(code)) {
      out += visible_escape(code);
    } else {
      out.append(bytes);
    }
    rest.remove_prefix(length);
  }
  return out;
}

// Characters a reader cannot see, or that reorder what follows them on screen.
bool is_unseen(std::uint32_t code) {
  const bool c0_or_del = code < 0x20 || code == 0x7F;
  const bool c1 = code >= 0x80 && code <= 0x9F;
  const bool bidi = (code >= 0x202A && code <= 0x202E) || (code >= 0x2066 && code <= 0x2069);
  return c0_or_del || c1 || bidi;
}

bool is_terminal_control(std::uint32_t code) {
  return code != '\t' && code != '\n' && is_unseen(code);
}

bool is_markup_control(std::uint32_t code) {
  if (code == '\t' || code == '\n' || code == '\r') return false;
  return is_unseen(code) || code == 0xFFFE || code == 0xFFFF;  // the last two: XML 1.0
}

}  // namespace

std::string terminal_text(std::string_view text) {
  return escaped_where(text, is_terminal_control);
}

std::string terminal_line(std::string_view text) {
  return escaped_where(text, [](std::uint32_t code) { return code != '\t' && is_unseen(code); });
}

std::string markup_text(std::string_view text) { return escaped_where(text, is_markup_control); }

}  // namespace raygate
