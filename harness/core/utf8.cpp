#include "core/utf8.h"

#include <cstdio>

namespace raygate {
namespace {

// What the bytes at the start of a text are: a well-formed sequence of `length` bytes, or
// (valid = false) the maximal subpart of one that cannot be completed, at least one byte.
struct Sequence {
  std::size_t length = 0;
  bool valid = false;
};

// The range the second byte of a sequence must be in: the lead byte narrows it where the
// plain 80..BF would allow an overlong form (E0, F0), a surrogate (ED) or more than U+10FFFF.
struct SecondByte {
  unsigned char low = 0x80;
  unsigned char high = 0xBF;
};

SecondByte second_byte_range(unsigned char lead) {
  switch (lead) {
    case 0xE0: return {0xA0, 0xBF};
    case 0xED: return {0x80, 0x9F};
    case 0xF0: return {0x90, 0xBF};
    case 0xF4: return {0x80, 0x8F};
    default: return {};
  }
}

// Bytes in the sequence a lead byte starts; 0 for bytes that never start one (80..C1, F5..FF).
std::size_t expected_length(unsigned char lead) {
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF) return 2;
  if (lead >= 0xE0 && lead <= 0xEF) return 3;
  if (lead >= 0xF0 && lead <= 0xF4) return 4;
  return 0;
}

Sequence next_sequence(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const std::size_t expected = expected_length(byte(0));
  if (expected == 0) return {1, false};
  const SecondByte second = second_byte_range(byte(0));
  std::size_t length = 1;
  for (; length < expected && length < text.size(); ++length) {
    const unsigned char low = length == 1 ? second.low : 0x80;
    const unsigned char high = length == 1 ? second.high : 0xBF;
    if (byte(length) < low || byte(length) > high) return {length, false};
  }
  return {length, length == expected};
}

}  // namespace

bool is_valid_utf8(std::string_view text) {
  while (!text.empty()) {
    const Sequence sequence = next_sequence(text);
    if (!sequence.valid) return false;
    text.remove_prefix(sequence.length);
  }
  return true;
}

std::string utf8_value_problem(const std::string& text) {
  std::string_view rest = text;
  while (!rest.empty()) {
    const Sequence sequence = next_sequence(rest);
    if (!sequence.valid) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(rest.front()));
      return std::string("not UTF-8 text (byte ") + hex + " at " +
             std::to_string(text.size() - rest.size() + 1) +
             "): raygate writes names and paths into JSON documents, which hold only text; "
             "rename it";
    }
    rest.remove_prefix(sequence.length);
  }
  return "";
}

std::string repaired_utf8(std::string_view text) {
  if (is_valid_utf8(text)) return std::string(text);  // the common case: no copy-and-check
  std::string out;
  out.reserve(text.size() + 8);
  while (!text.empty()) {
    const Sequence sequence = next_sequence(text);
    if (sequence.valid) {
      out.append(text.substr(0, sequence.length));
    } else {
      out.append(kReplacementCharacter);
    }
    text.remove_prefix(sequence.length);
  }
  return out;
}

std::string latin1_to_utf8(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size() * 2);
  for (const char c : bytes) {
    const auto code = static_cast<unsigned char>(c);
    if (code < 0x80) {
      out.push_back(c);
    } else {
      out.push_back(static_cast<char>(0xC0 | (code >> 6)));
      out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
    }
  }
  return out;
}

std::size_t utf8_sequence_length(std::string_view text) {
  if (text.empty()) return 0;
  const Sequence sequence = next_sequence(text);
  return sequence.valid ? sequence.length : 0;
}

}  // namespace raygate
