// Primitives per scene: the n of the growth fit. Counted from the NFF a generator writes (spheres
// `s`, cones `c`, polygons `p`, patches `pp`), so it is the scene the tracers were given.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>

namespace raygate {

// Generates the scene without keeping its text (balls at size 6 is 30 MB) and counts primitive
// lines. Throws std::invalid_argument for an unknown scene or a size out of range.
std::int64_t count_primitives(const std::string& scene, int size);

}  // namespace raygate

namespace raygate {

// count_primitives, remembering each (scene, size) it has counted: a projection walks every
// size of a family, and a report counts the same scenes again.
class CachedPrimitiveCount {
 public:
  std::int64_t operator()(const std::string& scene, int size);

 private:
  std::map<std::pair<std::string, int>, std::int64_t> counts_;
};

}  // namespace raygate
