// NFF reader. NFF is a stream of whitespace-separated tokens in which only two things care about
// lines: `#` starts a comment that runs to the end of the line, and a light (`l x y z [r g b]`)
// has an optional colour that must be on the same line. So the file is split into tokens that
// remember their line, and the entities are read from that list.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scene.h"

namespace nff {
namespace {

struct Token {
  std::string text;
  int line = 0;
};

std::vector<Token> tokenize(std::istream& in) {
  std::vector<Token> tokens;
  std::string line_text;
  for (int line = 1; std::getline(in, line_text); ++line) {
    const std::size_t hash = line_text.find('#');
    if (hash != std::string::npos) line_text.erase(hash);
    std::istringstream words(line_text);
    for (std::string word; words >> word;) tokens.push_back({word, line});
  }
  return tokens;
}

class Reader {
 public:
  Reader(std::string path, std::vector<Token> tokens)
      : path_(std::move(path)), tokens_(std::move(tokens)) {}

  Scene read() {
    while (next_ < tokens_.size()) entity(tokens_[next_++]);
    if (scene_.polygons.empty() && scene_.spheres.empty() && scene_.cones.empty() &&
        scene_.triangles.empty()) {
      fail(last_line(), "the scene has no shapes");
    }
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw std::runtime_error(path_ + ":" + std::to_string(line) + ": " + what);
  }

  int last_line() const { return tokens_.empty() ? 1 : tokens_.back().line; }

  double number(const char* what) {
    if (next_ >= tokens_.size())
      fail(last_line(), std::string("expected ") + what + ", found the end of the file");
    const Token& token = tokens_[next_++];
    try {
      std::size_t used = 0;
      const double value = std::stod(token.text, &used);
      if (used == token.text.size()) return value;
    } catch (const std::exception&) {
    }
    fail(token.line, std::string("expected ") + what + ", found '" + token.text + "'");
  }

  Vec3 vec(const char* what) {
    const double x = number(what), y = number(what), z = number(what);
    return {x, y, z};
  }

  int count(const char* what, int minimum) {
    const int line = next_ < tokens_.size() ? tokens_[next_].line : last_line();
    const double n = number(what);
    if (n != static_cast<int>(n) || n < minimum) {
      fail(line,
           std::string(what) + " must be a whole number of at least " + std::to_string(minimum));
    }
    return static_cast<int>(n);
  }

  // Shapes before the first `f` get the default material (white, diffuse).
  int material() {
    if (scene_.materials.empty()) scene_.materials.push_back(Material{});
    return static_cast<int>(scene_.materials.size()) - 1;
  }

  void light(int line) {
    Light light{vec("a light position"), {1, 1, 1}};
    if (next_ < tokens_.size() && tokens_[next_].line == line) light.colour = vec("a light colour");
    scene_.lights.push_back(light);
  }

  void polygon() {
    Polygon polygon;
    const int n = count("a vertex count", 3);
    for (int i = 0; i < n; ++i) polygon.vertices.push_back(vec("a polygon vertex"));
    Vec3 newell;  // robust for concave outlines and nearly collinear first vertices
    for (int i = 0; i < n; ++i) {
      const Vec3 a = polygon.vertices[i], b = polygon.vertices[(i + 1) % n];
      newell +=
          Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    if (length(newell) == 0) return;  // zero area: no ray can hit it
    polygon.normal = normalize(newell);
    polygon.material = material();
    scene_.polygons.push_back(std::move(polygon));
  }

  // A patch as a fan of triangles around its first vertex (SPD's patches are convex).
  void patch() {
    const int n = count("a vertex count", 3);
    std::vector<Vec3> points, normals;
    for (int i = 0; i < n; ++i) {
      points.push_back(vec("a patch vertex"));
      normals.push_back(normalize(vec("a patch vertex normal")));
    }
    for (int i = 2; i < n; ++i) {
      scene_.triangles.push_back({points[0], points[i - 1], points[i], normals[0], normals[i - 1],
                                  normals[i], material()});
    }
  }

  void entity(const Token& token) {
    const std::string& word = token.text;
    View& view = scene_.view;
    if (word == "v") return;  // the view's keywords follow
    if (word == "from") view.from = vec("a 'from' point");
    else if (word == "at") view.at = vec("an 'at' point");
    else if (word == "up") view.up = vec("an 'up' vector");
    else if (word == "angle") view.angle_degrees = number("an angle in degrees");
    else if (word == "hither") view.hither = number("a hither distance");
    else if (word == "resolution") {
      view.width = count("a width", 1);
      view.height = count("a height", 1);
    } else if (word == "b") scene_.background = vec("a background colour");
    else if (word == "l") light(token.line);
    else if (word == "f") {
      Material m;
      m.colour = vec("a colour");
      m.kd = number("Kd");
      m.ks = number("Ks");
      m.shine = number("Shine");
      m.transmittance = number("T");
      m.ior = number("an index of refraction");
      scene_.materials.push_back(m);
    } else if (word == "s") {
      const Vec3 centre = vec("a sphere centre");
      scene_.spheres.push_back({centre, std::abs(number("a sphere radius")), material()});
    } else if (word == "c") {
      Cone cone;
      cone.base = vec("a cone base point");
      cone.base_radius = std::abs(number("a cone base radius"));
      cone.apex = vec("a cone apex point");
      cone.apex_radius = std::abs(number("a cone apex radius"));
      cone.material = material();
      scene_.cones.push_back(cone);
    } else if (word == "p") polygon();
    else if (word == "pp") patch();
    else fail(token.line, "unknown NFF entity '" + word + "'");
  }

  std::string path_;
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  Scene scene_;
};

}  // namespace

Scene read_nff(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the scene file");
  return Reader(path, tokenize(in)).read();
}

}  // namespace nff
