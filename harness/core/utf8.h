// UTF-8 for text raygate did not write: commit subjects, author and ref names, paths and rows
// read back from a store. Results documents, JSON output and the store need valid UTF-8 (a
// single stray Latin-1 byte made nlohmann::json throw while writing, and the measurement was
// lost), so such text is repaired where it enters, never rejected. One validator and one
// repairer, so every stage agrees on what "valid" means.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace raygate {

// U+FFFD REPLACEMENT CHARACTER, what an invalid byte sequence becomes.
inline constexpr std::string_view kReplacementCharacter = "\xEF\xBF\xBD";

// Well-formed UTF-8 as Unicode defines it (Table 3-7): no overlong forms, no surrogates
// (U+D800..U+DFFF), nothing above U+10FFFF, no truncated sequence.
bool is_valid_utf8(std::string_view text);

// Why a value the user gave cannot be taken as text (a path or name with bytes that are not
// UTF-8): it would be written into JSON, which holds only text. "" when it is UTF-8. A check on
// every option (cli/finite_numbers.h): paths cannot be repaired without naming another file.
std::string utf8_value_problem(const std::string& text);

// `text` with every maximal invalid subpart replaced by one U+FFFD (Unicode's recommended
// practice, also the WHATWG decoder's): "\xE2\x82" (a truncated euro sign) is one U+FFFD,
// "\xC0\xAF" (an overlong '/') two. Valid text comes back unchanged.
std::string repaired_utf8(std::string_view text);

// ISO-8859-1 bytes as UTF-8: every byte is the code point of the same number.
std::string latin1_to_utf8(std::string_view bytes);

// Length in bytes of the well-formed sequence at the start of `text` (1 to 4), or 0 when the
// text is empty or starts with an invalid sequence. For walking valid text code point by point.
std::size_t utf8_sequence_length(std::string_view text);

}  // namespace raygate
