// The NFF reader's driver (spd-spec.md §1): errors, value reading, the entity dispatch and the
// view block. The other entities are in entities.cpp, file access in file.cpp.
#include "nff/parser.h"

#include <string>
#include <utility>

#include "nff/reader.h"

namespace raygate::nff {
namespace {

// "path:line:column: detail"; a location with line 0 (the file as a whole) is just "path: ".
std::string with_location(const FileLoc& loc, const std::string& detail) {
  if (loc.line <= 0) return loc.path + ": " + detail;
  return loc.path + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column) + ": " +
         detail;
}

}  // namespace

ParseError::ParseError(FileLoc loc, const std::string& message)
    : std::runtime_error(with_location(loc, message)), loc_(std::move(loc)), detail_(message) {}

Scene parse_nff(std::string_view text, const std::string& path) {
  return detail::Reader(text, path).read();
}

}  // namespace raygate::nff

namespace raygate::nff::detail {

std::string Field::words(std::string_view article) const {
  std::string out(article);
  if (!axis.empty()) {
    out += axis;
    out += " of ";
    if (!part.empty()) out += "the ";
  }
  if (!part.empty()) {
    out += part;
    out += " of ";
  }
  if (vertex > 0) {
    out += "vertex " + std::to_string(vertex) + " of " + std::to_string(count) + " of ";
  }
  out += entity;
  return out;
}

Reader::Reader(std::string_view text, const std::string& path) : lexer_(text), path_(path) {
  scene_.path = path;
}

Scene Reader::read() {
  if (lexer_.empty_input()) fail_with(lexer_.peek(), "expected an NFF scene, found an empty file");
  for (Token keyword = lexer_.next(); !keyword.at_end(); keyword = lexer_.next()) {
    read_entity(keyword);
    last_keyword_ = keyword;
  }
  if (!have_view_) fail(lexer_.peek(), "a view (v)");
  return std::move(scene_);
}

void Reader::read_entity(const Token& keyword) {
  const std::string_view k = keyword.text;
  if (k == "v") return read_view(keyword);
  if (k == "b") return read_background();
  if (k == "l") return read_light();
  if (k == "f") return read_material(keyword);
  if (k == "c") return read_cone(keyword);
  if (k == "s") return read_sphere(keyword);
  if (k == "p") return read_polygon(keyword);
  if (k == "pp") return read_patch(keyword);
  fail_unknown_keyword(keyword);
}

void Reader::fail_unknown_keyword(const Token& token) const {
  const std::string expected = "expected an NFF keyword (v, b, l, f, c, s, p, pp), found ";
  // A number here is most often one too many for the entity before, e.g. a polygon whose
  // vertex count is lower than the number of vertices written.
  if (is_number(token.text) && !last_keyword_.at_end()) {
    fail_with(token, expected + describe(token) + " (one number too many for the " +
                         std::string(entity_name(last_keyword_.text)) + " at line " +
                         std::to_string(last_keyword_.line) + "?)");
  }
  fail_with(at_first_control_byte(token),
            expected + describe(token) + keyword_suggestion(token.text, false));
}

// `v` then its keywords. hither and resolution are optional (spd-spec.md §1.6); all may come in
// any order, each at most once. The block ends at the first token that is not a view keyword.
void Reader::read_view(const Token& keyword) {
  if (have_view_) {
    fail_with(keyword, "expected one view (v), found a second 'v' (the first is at line " +
                           std::to_string(view_keyword_.line) + ", column " +
                           std::to_string(view_keyword_.column) + ")");
  }
  have_view_ = true;
  view_keyword_ = keyword;
  bool seen[6] = {};
  for (;;) {
    const Token token = lexer_.peek();
    const int index = view_keyword_index(token.text);
    if (index < 0) {
      // A number ends the block too, so that it is reported as one too many for the view.
      const bool ends_block =
          token.at_end() || !entity_name(token.text).empty() || is_number(token.text);
      if (ends_block) break;
      fail_with(at_first_control_byte(token),
                "expected a view keyword (from, at, up, angle, hither, resolution), found " +
                    describe(token) + keyword_suggestion(token.text, true));
    }
    lexer_.next();
    if (seen[index]) {
      fail_with(token, "expected each view keyword once, found a second '" +
                           std::string(token.text) + "'");
    }
    seen[index] = true;
    read_view_keyword(index);
  }
  for (int i = 0; i < 4; ++i) {  // from, at, up and angle are required
    if (!seen[i]) fail(lexer_.peek(), "'" + std::string(kViewKeywords[i]) + "' in view (v)");
  }
}

void Reader::read_view_keyword(int index) {
  View& view = scene_.view;
  Token value;
  switch (index) {
    case 0: view.from = vector({.entity = "'from' in view (v)"}); break;
    case 1: view.at = vector({.entity = "'at' in view (v)"}); break;
    case 2: view.up = vector({.entity = "'up' in view (v)"}); break;
    case 3:
      view.angle_degrees = number({.entity = "view (v)", .part = "angle"}, &value);
      if (view.angle_degrees <= 0.0 || view.angle_degrees >= 180.0) {
        fail(value, "the angle of view (v) in degrees, above 0 and below 180");
      }
      break;
    case 4:
      view.hither = number({.entity = "view (v)", .part = "hither"}, &value);
      if (view.hither < 0.0) fail(value, "the hither of view (v) as 0 or more");
      break;
    default:
      view.width =
          integer({.entity = "view (v)", .part = "width of the resolution"}, 1, kMaxResolutionSide);
      view.height = integer({.entity = "view (v)", .part = "height of the resolution"}, 1,
                            kMaxResolutionSide);
      break;
  }
}

double Reader::number(const Field& field, Token* where) {
  const Token token = lexer_.next();
  double value = 0.0;
  switch (parse_double(token.text, value)) {
    case NumberStatus::ok: break;
    case NumberStatus::not_a_number: fail(token, field.words());
    case NumberStatus::not_finite: fail(token, field.words() + " as a finite number");
  }
  if (where != nullptr) *where = token;
  return value;
}

Vec3 Reader::vector(Field field, Token* where) {
  Vec3 v;
  field.axis = "x";
  v.x = number(field, where);
  field.axis = "y";
  v.y = number(field);
  field.axis = "z";
  v.z = number(field);
  return v;
}

Vec3 Reader::colour(Field field) {
  Vec3 c;
  field.axis = "red";
  c.x = number(field);
  field.axis = "green";
  c.y = number(field);
  field.axis = "blue";
  c.z = number(field);
  return c;
}

int Reader::integer(const Field& field, long long low, long long high) {
  const Token token = lexer_.next();
  long long value = 0;
  if (!parse_integer(token.text, value) || value < low || value > high) {
    fail(token, field.words() + " as an integer from " + std::to_string(low) + " to " +
                    std::to_string(high));
  }
  return static_cast<int>(value);
}

FileLoc Reader::loc(const Token& token) const { return {path_, token.line, token.column}; }

void Reader::fail(const Token& found, const std::string& expected) const {
  fail_with(at_first_control_byte(found), "expected " + expected + ", found " + describe(found));
}

void Reader::fail_with(const Token& at, const std::string& detail) const {
  throw ParseError(loc(at), detail);
}

}  // namespace raygate::nff::detail
