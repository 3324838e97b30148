#include "report/terminal.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <string_view>

#include "core/error.h"

namespace raygate {

ColourChoice parse_colour_choice(std::string_view text) {
  if (text == "auto") return ColourChoice::automatic;
  if (text == "always") return ColourChoice::always;
  if (text == "never") return ColourChoice::never;
  throw UsageError(fmt::format("--color {}: expected auto, always or never", text));
}

bool colour_wanted(ColourChoice choice, bool terminal, const char* no_color) {
  if (choice == ColourChoice::always) return true;
  if (choice == ColourChoice::never) return false;
  return terminal && (no_color == nullptr || *no_color == '\0');
}

bool is_terminal(std::FILE* stream) { return ::isatty(::fileno(stream)) == 1; }

bool Console::colour(std::FILE* stream) const {
  return colour_wanted(choice_, stream != nullptr && is_terminal(stream),
                       no_color_ ? "1" : nullptr);
}

// fputs, not fmt::print: chatter to a terminal that was closed (EIO) is dropped, not thrown, so
// a hang-up still ends with its own exit code and a kept document.
void Console::info(const std::string& text) const {
  if (!quiet_) std::fputs((terminal_text(text) + "\n").c_str(), stderr);
}

void Console::warning(const std::string& text) const {
  std::fputs(("raygate: warning: " + terminal_text(text) + "\n").c_str(), stderr);
}

void Console::problem(const std::string& text) const { std::fputs(text.c_str(), stderr); }

namespace {

// The byte at or before `at` where a UTF-8 character starts: a cut inside one would leave bytes
// no terminal can show.
std::size_t character_start(const std::string& text, std::size_t at) {
  while (at > 0 && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) --at;
  return at;
}

// Each word (a run without white space) over 240 bytes shown by its ends and its length: such a
// word is a path or a pasted value, and a 6,000-byte path once filled the error line. Its ends
// are what tell a user which one it was.
std::string shortened_long_words(const std::string& text) {
  constexpr std::size_t kLongest = 240;
  constexpr std::size_t kEnd = 100;
  std::string out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find_first_of(" \t\n", at), text.size());
    const std::size_t length = end - at;
    if (length <= kLongest) {
      out.append(text, at, length);
    } else {
      // "PATH: reason": the colon follows the length, as it followed the path.
      const std::size_t last =
          std::string_view(":;,").find(text[end - 1]) != std::string::npos ? end - 1 : end;
      const std::size_t head_end = character_start(text, at + kEnd);
      const std::size_t tail_start = character_start(text, last - kEnd);
      out += text.substr(at, head_end - at) + "…" + text.substr(tail_start, last - tail_start) +
             fmt::format(" ({} bytes)", last - at) + text.substr(last, end - last);
    }
    if (end < text.size()) out += text[end];
    at = end + 1;
  }
  return out;
}

}  // namespace

std::string bounded_message(std::string text) {
  text = shortened_long_words(text);
  constexpr std::size_t kMaxChars = 16 * 1024;
  if (text.size() <= kMaxChars) return text;
  const std::size_t cut = text.size() - kMaxChars;
  text.resize(kMaxChars);
  return text + fmt::format("... ({} more characters not shown)", cut);
}

std::string plain_usage_words(std::string text) {
  // "--store excludes --no-store": which is given is the user's choice, so both are named.
  const std::string_view excludes = " excludes ";
  if (const std::size_t at = text.find(excludes);
      at != std::string::npos && text.rfind("--", 0) == 0) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::size_t other = at + excludes.size();
    return text.substr(0, at) + " and " + text.substr(other, end - other) +
           " cannot be given together; give one" + text.substr(end);
  }
  // "files is required": CLI11's words for an argument left out, named as its help lists it.
  const std::string_view required = " is required";
  const std::size_t line_end = std::min(text.find('\n'), text.size());
  if (const std::string_view first(text.data(), line_end);
      first.ends_with(required) && !first.starts_with("-") &&
      first.find(' ') == line_end - required.size()) {
    return "no " + text.substr(0, line_end - required.size()) + " given; name at least one" +
           text.substr(line_end);
  }
  const std::string_view said = ": At Most 1 required but received ";
  const std::size_t at = text.find(said);
  if (at == std::string::npos) return text;
  const std::size_t digits = at + said.size();
  const std::size_t end = std::min(text.find_first_not_of("0123456789", digits), text.size());
  const std::string count = text.substr(digits, end - digits);
  return text.substr(0, at) + " is given " + count + " times; give it once" + text.substr(end);
}

void say_last_words(const std::string& line) {
  std::fputs((bounded_message(line) + "\n").c_str(), stderr);
  std::fflush(stderr);
}

}  // namespace raygate
