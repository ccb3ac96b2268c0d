#include <gtest/gtest.h>

#include "io/obj_reader.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace billow;

TEST(ObjReader, ReadsTrianglesQuadsAndCornerForms) {
  const TriMesh m = readObj(
      "# a unit square as a quad, then a triangle with v/vt/vn corners and negative indices\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvn 0 0 1\n"
      "f 1 2 3 4\n"
      "f -4/1/1 -3//1 -1\n");
  ASSERT_EQ(m.numVertices(), 4);
  ASSERT_EQ(m.numTriangles(), 3);
  EXPECT_EQ(m.F(0, 0), 0);
  EXPECT_EQ(m.F(1, 2), 3);
  EXPECT_EQ(m.F(2, 0), 0);
  EXPECT_EQ(m.F(2, 1), 1);
  EXPECT_EQ(m.F(2, 2), 3);
  EXPECT_DOUBLE_EQ(m.V(2, 1), 1.0);
}

TEST(ObjReader, SharedMeshesHaveTheirDocumentedCounts) {
  const TriMesh sphere = test::loadShared("sphere.obj");
  EXPECT_EQ(sphere.numVertices(), 642);
  EXPECT_EQ(sphere.numTriangles(), 1280);
  const TriMesh spot = test::loadShared("spot.obj");
  EXPECT_EQ(spot.numVertices(), 2930);
  EXPECT_EQ(spot.numTriangles(), 5856);
}

TEST(ObjReader, MalformedInputNamesTheLine) {
  try {
    readObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    FAIL() << "an out-of-range index must be rejected";
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "obj.syntax");
    EXPECT_NE(std::string(e.what()).find("line 4"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readObj("v 0 zero 0\n"), Error);
  EXPECT_THROW(readObj("v 0 0 0\nv 1 0 0\nf 1 2\n"), Error);
  EXPECT_THROW(readObj("v 0 0 0\n"), Error);  // no faces
  EXPECT_THROW(readObj("\x01\x02garbage\xff\n"), Error);
}

TEST(ObjReader, RefusesTooManyVertices) {
  MeshReadOptions small;
  small.maxVertices = 2;
  try {
    readObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", small);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "mesh.too-large");
  }
}
