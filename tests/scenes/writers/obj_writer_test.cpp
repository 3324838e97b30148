// The Wavefront OBJ + MTL writer: an `o` and a `usemtl` per NFF primitive, spheres and cones
// tessellated with vertex normals, concave polygons split into triangles, patch normals kept,
// global 1-based indices, and one MTL material per `f`.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

#include "writer_test_support.h"

namespace raygate::writers {
namespace {

struct ObjObject {
  std::string name;
  std::string material;
  std::size_t first_position = 0;  // 1-based number of this object's first `v`
  std::size_t first_normal = 0;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<std::string> faces;  // the text after "f"
};

std::vector<ObjObject> read_objects(const std::string& obj) {
  std::vector<ObjObject> objects;
  std::size_t positions = 0;
  std::size_t normals = 0;
  std::istringstream in(obj);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "o") {
      objects.push_back({});
      words >> objects.back().name;
      objects.back().first_position = positions + 1;
      objects.back().first_normal = normals + 1;
    } else if (objects.empty()) {
      continue;
    } else if (key == "usemtl") {
      words >> objects.back().material;
    } else if (key == "v" || key == "vn") {
      Vec3 p;
      words >> p.x >> p.y >> p.z;
      (key == "v" ? objects.back().positions : objects.back().normals).push_back(p);
      ++(key == "v" ? positions : normals);
    } else if (key == "f") {
      objects.back().faces.push_back(line.substr(1));
    }
  }
  return objects;
}

TEST(ObjWriter, OneNamedObjectWithItsMaterialPerPrimitive) {
  const std::string obj = test::obj_text(test::parse());
  EXPECT_EQ(obj.rfind("# Wavefront OBJ converted from scene.nff", 0), 0u);
  EXPECT_NE(obj.find("\nmtllib scene.mtl\n"), std::string::npos);
  const std::vector<ObjObject> objects = read_objects(obj);
  ASSERT_EQ(objects.size(), 5u);
  const char* names[] = {"sphere1", "cone1", "cone2", "polygon1", "patch1"};
  const char* materials[] = {"f1", "f2", "f2", "f3", "f3"};
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(objects[i].name, names[i]);
    EXPECT_EQ(objects[i].material, materials[i]);
  }
}

TEST(ObjWriter, SphereIsTessellatedWithNormals) {
  const std::vector<ObjObject> objects = read_objects(test::obj_text(test::parse()));
  const ObjObject& sphere = objects.at(0);
  EXPECT_EQ(sphere.positions.size(), 2u + 16u * 7u);  // default: 16 segments, 8 bands
  EXPECT_EQ(sphere.normals.size(), sphere.positions.size());
  EXPECT_EQ(sphere.faces.size(), 2u * 16u * 7u);
  for (const Vec3& p : sphere.positions) EXPECT_NEAR(length(p - Vec3{1, 2, 3}), 0.5, 1e-9);
  EXPECT_EQ(sphere.faces[0], " 1//1 2//2 3//3");
}

TEST(ObjWriter, SegmentsOptionSetsTheResolution) {
  const std::vector<ObjObject> objects =
      read_objects(test::obj_text(test::parse(), {.segments = 8}));
  EXPECT_EQ(objects.at(0).faces.size(), 2u * 8u * 3u);
  EXPECT_EQ(objects.at(1).faces.size(), 16u);  // the cone: 8 quads
  EXPECT_THROW(test::obj_text(test::parse(), {.segments = 2}), std::invalid_argument);
}

TEST(ObjWriter, ConesAreOpen) {
  const std::vector<ObjObject> objects = read_objects(test::obj_text(test::parse()));
  const ObjObject& cone = objects.at(1);
  EXPECT_EQ(cone.positions.size(), 32u);  // 16 on each rim, no cap centres
  EXPECT_EQ(cone.faces.size(), 32u);
  for (const Vec3& p : cone.positions) {
    EXPECT_NEAR(std::hypot(p.x, p.y), p.z == 0.0 ? 1.0 : 0.25, 1e-9);
  }
}

TEST(ObjWriter, ConcavePolygonIsSixTrianglesWithGlobalIndices) {
  const std::vector<ObjObject> objects = read_objects(test::obj_text(test::parse()));
  const ObjObject& polygon = objects.at(3);
  EXPECT_EQ(polygon.positions.size(), 8u);
  EXPECT_TRUE(polygon.normals.empty());
  ASSERT_EQ(polygon.faces.size(), 6u);
  for (const std::string& face : polygon.faces) {
    for (double index : test::numbers_in(face)) {
      EXPECT_GE(index, double(polygon.first_position));
      EXPECT_LT(index, double(polygon.first_position + 8));
    }
  }
}

TEST(ObjWriter, PatchNormalsAreKept) {
  const std::vector<ObjObject> objects = read_objects(test::obj_text(test::parse()));
  const ObjObject& patch = objects.at(4);
  ASSERT_EQ(patch.normals.size(), 3u);
  EXPECT_EQ(patch.normals[1], (Vec3{0.6, 0, 0.8}));
  const std::size_t v = patch.first_position;
  const std::size_t n = patch.first_normal;
  EXPECT_EQ(patch.faces.at(0), " " + std::to_string(v) + "//" + std::to_string(n) + " " +
                                   std::to_string(v + 1) + "//" + std::to_string(n + 1) + " " +
                                   std::to_string(v + 2) + "//" + std::to_string(n + 2));
}

TEST(ObjWriter, MtlHasOneMaterialPerFillLine) {
  const std::string mtl = test::mtl_text(test::parse());
  EXPECT_EQ(test::count(mtl, "newmtl "), 3u);
  EXPECT_NE(
      mtl.find("newmtl f1\nKa 0.1 0 0\nKd 0.7 0 0\nKs 0.3 0.3 0.3\nNs 20\nd 1\nNi 1\nillum 3\n"),
      std::string::npos);
  EXPECT_NE(
      mtl.find("newmtl f2\nKa 0 0.1 0\nKd 0 0.2 0\nKs 0 0 0\nNs 1000\nd 0.2\nNi 1.5\nillum 6\n"),
      std::string::npos);
  EXPECT_NE(mtl.find("newmtl f3\nKa 0 0 0.1\nKd 0 0 1\nKs 0 0 0\nNs 1000\nd 1\nNi 1\nillum 2\n"),
            std::string::npos);
}

}  // namespace
}  // namespace raygate::writers
