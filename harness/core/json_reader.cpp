#include "core/json_reader.h"

#include <algorithm>
#include <iterator>
#include <set>
#include <vector>

#include "core/fs.h"

namespace raygate {

namespace {

using Json = nlohmann::json;

// Walks the text for nlohmann's parser and remembers how far it read: the parser's callback is
// told what it parsed but not where, and a message without a line sends a person hunting.
class CountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* at, const char* begin, std::size_t* read)
      : at_(at), begin_(begin), read_(read) {}
  reference operator*() const { return *at_; }
  CountingIterator& operator++() {
    ++at_;
    *read_ = static_cast<std::size_t>(at_ - begin_);
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
  bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

 private:
  const char* at_;
  const char* begin_;
  std::size_t* read_;
};

// One open object or array while the parser is inside it.
struct OpenContainer {
  bool is_object = false;
  std::set<std::string> keys;  // objects: the keys seen so far
  std::string key;             // objects: the member being read
  std::size_t index = 0;       // arrays: the element being read
};

bool is_identifier(const std::string& key) {
  if (key.empty() || (key[0] >= '0' && key[0] <= '9')) return false;
  for (const char c : key) {
    const bool word =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!word) return false;
  }
  return true;
}

std::string step(const OpenContainer& frame) {
  if (!frame.is_object) return "[" + std::to_string(frame.index) + "]";
  return is_identifier(frame.key) ? "." + frame.key : "[" + Json(frame.key).dump() + "]";
}

// "$" and a step into each of the first `count` open containers: count = open.size() - 1 is
// the innermost container itself, open.size() the value being read in it.
std::string path_through(const std::vector<OpenContainer>& open, std::size_t count) {
  std::string path = "$";
  for (std::size_t i = 0; i < count && i < open.size(); ++i) path += step(open[i]);
  return path;
}

// 1-based line and column of byte `offset`.
std::pair<std::size_t, std::size_t> line_and_column(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  std::size_t line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return {line, offset - line_start + 1};
}

// Where the string that ends just before `end` (its closing quote at end - 1) opens.
std::size_t string_start(std::string_view text, std::size_t end) {
  for (std::size_t i = end >= 2 ? end - 2 : 0; i > 0; --i) {
    if (text[i] != '"') continue;
    std::size_t backslashes = 0;
    for (std::size_t j = i; j > 0 && text[j - 1] == '\\'; --j) ++backslashes;
    if (backslashes % 2 == 0) return i;
  }
  return 0;
}

bool in_number(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// Where the number the parser just read starts (it has read one character past it, or to EOF).
std::size_t number_start(std::string_view text, std::size_t read) {
  std::size_t end = std::min(read, text.size());
  if (end > 0 && !in_number(text[end - 1])) --end;
  while (end > 0 && in_number(text[end - 1])) --end;
  return end;
}

// nlohmann's "[json.exception.parse_error.101] parse error at line L, column C: <detail>". Its
// line and column are not used: after a token that ended at a newline it says column 0. The
// byte it stopped at is right; the place is the last character it read.
[[noreturn]] void throw_syntax_error(const Json::parse_error& e, std::string_view text,
                                     const std::string& origin) {
  // Found, not matched: std::regex recurses a frame per character of a long "last read" token.
  const std::string what = e.what();
  const std::size_t said = what.find("column ");
  const std::size_t colon = said == std::string::npos ? said : what.find(": ", said);
  const std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
  const auto [line, column] = line_and_column(text, e.byte == 0 ? 0 : e.byte - 1);
  throw JsonInputError(origin, line, column, "", "not JSON: " + detail);
}

}  // namespace

std::string plain_exception_text(const std::exception& e) {
  const std::string what = e.what();
  constexpr std::string_view kLabel = "[json.exception.";
  if (!what.starts_with(kLabel)) return what;
  const std::size_t end = what.find("] ");
  return end == std::string::npos ? what : what.substr(end + 2);
}

JsonInputError::JsonInputError(std::string origin, std::size_t line, std::size_t column,
                               std::string json_path, std::string problem)
    : UsageError(origin + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                 (json_path.empty() ? "" : json_path + ": ") + problem),
      origin_(std::move(origin)),
      line_(line),
      column_(column),
      json_path_(std::move(json_path)),
      problem_(std::move(problem)) {}

// No file raygate reads nests past about 10 levels. Deeper input is refused while it is parsed:
// code that walks a document recursively (import's check of the keys it keeps, dump) overflowed
// its stack on 20,000 nested arrays (a sweep), where the parser itself does not recurse.
constexpr std::size_t kMaxNesting = 128;

[[noreturn]] void throw_too_deep(std::string_view text, std::size_t read,
                                 const std::vector<OpenContainer>& open,
                                 const std::string& origin) {
  constexpr std::size_t kShownLevels = 6;
  std::string path = path_through(open, std::min(open.size(), kShownLevels));
  if (open.size() > kShownLevels) path += "...";
  const auto [line, column] = line_and_column(text, read > 0 ? read - 1 : 0);
  throw JsonInputError(origin, line, column, path,
                       "nested more than " + std::to_string(kMaxNesting) +
                           " levels deep (no raygate file nests past about 10)");
}

Json parse_json_input(std::string_view text, const std::string& origin) {
  using Event = Json::parse_event_t;
  std::size_t read = 0;
  std::vector<OpenContainer> open;
  const auto track = [&](int /*depth*/, Event event, Json& parsed) {
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        if (open.size() >= kMaxNesting) throw_too_deep(text, read, open, origin);
        open.push_back({event == Event::object_start, {}, {}, 0});
        break;
      case Event::key: {
        std::string key = parsed.get<std::string>();
        if (!open.back().keys.insert(key).second) {
          const auto [line, column] = line_and_column(text, string_start(text, read));
          throw JsonInputError(
              origin, line, column, path_through(open, open.size() - 1),
              "duplicate key '" + key + "' (JSON keeps only one of them; remove the other)");
        }
        open.back().key = std::move(key);
        break;
      }
      case Event::object_end:
      case Event::array_end:
        open.pop_back();
        if (!open.empty() && !open.back().is_object) ++open.back().index;
        break;
      case Event::value:
        if (!open.empty() && !open.back().is_object) ++open.back().index;
        break;
    }
    return true;
  };
  const CountingIterator first(text.data(), text.data(), &read);
  const CountingIterator last(text.data() + text.size(), text.data(), &read);
  try {
    return Json::parse(first, last, track);
  } catch (const Json::parse_error& e) {
    throw_syntax_error(e, text, origin);
  } catch (const Json::out_of_range&) {  // 406: a number past a double's range
    const std::size_t start = number_start(text, read);
    std::size_t end = start;
    while (end < text.size() && in_number(text[end])) ++end;
    constexpr std::size_t kShown = 40;  // "1" and 5000 zeros is said, not printed
    std::string number(text.substr(start, std::min(end - start, kShown)));
    if (end - start > kShown) number += "...";
    const auto [line, column] = line_and_column(text, start);
    throw JsonInputError(
        origin, line, column, path_through(open, open.size()),
        "number " + number + " is out of range (a double holds magnitudes up to about 1.8e308)");
  }
}

std::string read_json_text(const std::filesystem::path& file) {
  constexpr std::uintmax_t kMaxBytes = std::uintmax_t{256} << 20;
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(file, error);
  if (!error && bytes > kMaxBytes) {
    throw UsageError(file.string() + ": is " + std::to_string(bytes >> 20) +
                     " MiB; raygate reads JSON files of at most 256 MiB (a results document of "
                     "13 scenes is a few MB)");
  }
  return read_file(file);
}

Json read_json_file(const std::filesystem::path& file) {
  return parse_json_input(read_json_text(file), file.string());
}

}  // namespace raygate
