// Private to the NFF reader: the state of one parse and the entity readers. parser.cpp holds the
// driver and the view block, entities.cpp the other entities, suggest.cpp the "did you mean".
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "nff/lexer.h"
#include "nff/parser.h"

namespace raygate::nff::detail {

// Names a value the reader expects, e.g. "the x of the normal of vertex 2 of 3 of patch (pp)".
// Kept in parts and worded only when an error is thrown, so that reading stays cheap.
struct Field {
  std::string_view entity = {};  // "sphere (s)"
  std::string_view part = {};    // "centre", "radius", "normal"; empty for a bare polygon vertex
  std::string_view axis = {};    // "x", "red"; empty for a scalar
  long long vertex = 0;          // 1-based vertex number, 0 when not a vertex
  long long count = 0;           // the polygon's vertex count, with `vertex`

  std::string words(std::string_view article = "the ") const;
};

class Reader {
 public:
  Reader(std::string_view text, const std::string& path);
  Scene read();

 private:
  // parser.cpp
  void read_entity(const Token& keyword);
  void read_view(const Token& keyword);
  void read_view_keyword(int index);
  [[noreturn]] void fail_unknown_keyword(const Token& token) const;

  // entities.cpp
  void read_background();
  void read_light();
  void read_material(const Token& keyword);
  void read_cone(const Token& keyword);
  void read_sphere(const Token& keyword);
  void read_polygon(const Token& keyword);
  void read_patch(const Token& keyword);
  long long read_vertex_count(std::string_view entity);
  void check_polygon(const Token& keyword, std::string_view entity,
                     const std::vector<Vec3>& vertices) const;
  int material_for(const Token& keyword) const;

  // Reading values (parser.cpp). `where`, when given, receives the token that was read so a
  // later check can point at it.
  double number(const Field& field, Token* where = nullptr);
  Vec3 vector(Field field, Token* where = nullptr);
  Vec3 colour(Field field);  // like vector(), named red, green and blue
  int integer(const Field& field, long long low, long long high);

  FileLoc loc(const Token& token) const;
  // Throws "expected <expected>, found <token>" (`expected` without the word "expected"),
  // pointing at the token, or at its first control byte if it has one.
  [[noreturn]] void fail(const Token& found, const std::string& expected) const;
  // Throws with a message already worded, pointing at `at`.
  [[noreturn]] void fail_with(const Token& at, const std::string& detail) const;

  Lexer lexer_;
  const std::string& path_;
  Scene scene_;
  bool have_view_ = false;
  Token view_keyword_;
  Token last_keyword_;  // the entity read last, for "one number too many" hints
};

// The did-you-mean for an unknown keyword: "; did you mean 's'?" or empty. Inside a view
// block, view keywords come first. suggest.cpp.
std::string keyword_suggestion(std::string_view token, bool in_view);
// The index of a view keyword (from, at, up, angle, hither, resolution) or -1.
int view_keyword_index(std::string_view token);
extern const char* const kViewKeywords[6];
// The spelled-out name of an entity keyword, e.g. "sphere (s)", or empty when not one.
std::string_view entity_name(std::string_view keyword);

}  // namespace raygate::nff::detail
