// writeObj (io/obj_writer.hpp), how the CLI hands inflated shapes to other tools: its text must read back
// through the project's own OBJ reader as the same mesh (1-based faces, the same triangles in the same order),
// with coordinates to the nine significant digits it prints.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/obj_reader.hpp"
#include "io/obj_writer.hpp"
#include "util/error.hpp"

using namespace billow;

namespace {

// Four triangles over four points, on coordinates that nine digits print exactly.
TriMesh printableTetrahedron() {
  TriMesh m;
  m.V.resize(4, 3);
  m.V << 0, 0, 0, 1.5, 0, 0, 0, -2.25, 0, 0.125, 0.5, 1e-3;
  m.F.resize(4, 3);
  m.F << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2;
  return m;
}

}  // namespace

TEST(ObjWriter, AMeshRoundTripsThroughTheReader) {
  const TriMesh m = printableTetrahedron();
  const TriMesh back = readObj(writeObj(m.V, m.F));
  ASSERT_EQ(back.numVertices(), 4);
  ASSERT_EQ(back.numTriangles(), 4);
  EXPECT_EQ(back.V, m.V);
  EXPECT_EQ(back.F, m.F) << "faces keep their vertex order (and so their orientation)";
}

TEST(ObjWriter, FacesAreOneBasedVAndFLines) {
  const TriMesh m = printableTetrahedron();
  const std::string text = writeObj(m.V, m.F);
  EXPECT_EQ(text.rfind("v 0 0 0\nv 1.5 0 0\nv 0 -2.25 0\nv 0.125 0.5 0.001\n", 0), 0u) << text;
  EXPECT_NE(text.find("\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(ObjWriter, ACommentBecomesTheFirstLineAndIsIgnoredWhenRead) {
  const TriMesh m = printableTetrahedron();
  const std::string text = writeObj(m.V, m.F, "billow inflated shape (outer surface)");
  EXPECT_EQ(text.rfind("# billow inflated shape (outer surface)\nv ", 0), 0u) << text;
  const TriMesh back = readObj(text);
  EXPECT_EQ(back.V, m.V);
  EXPECT_EQ(back.F, m.F);
  EXPECT_EQ(writeObj(m.V, m.F).rfind("v ", 0), 0u) << "no comment line without a comment";
  // A comment of two lines stays a comment: its second line adds no vertex.
  const std::string two = writeObj(m.V, m.F, "first\nv 1 2 3");
  EXPECT_EQ(two.rfind("# first\n# v 1 2 3\nv ", 0), 0u) << two;
  EXPECT_EQ(readObj(two).V, m.V);
}

TEST(ObjWriter, CoordinatesKeepNineSignificantDigits) {
  // %.9g rounds to nine significant digits: a relative error of at most half a unit in the ninth digit,
  // 5e-9, for any magnitude (lengths in metres or millimetres alike); the reader's own rounding adds at most
  // one unit in the last place of a double.
  TriMesh m;
  m.V.resize(3, 3);
  m.V << 1.0 / 3, -2.0 / 7, 123456.789012345, 1e-7 * M_PI, 6.02214076e23, -std::sqrt(2.0), 0.1, 0.2, 0.3;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  const TriMesh back = readObj(writeObj(m.V, m.F));
  ASSERT_EQ(back.numVertices(), 3);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_LE(std::abs(back.V(i, k) - m.V(i, k)), (5e-9 + 1e-15) * std::abs(m.V(i, k))) << i << "," << k;
}

TEST(ObjWriter, AMeshWithoutTrianglesWritesOnlyVerticesWhichTheReaderRefuses) {
  // The reader needs a surface: a vertex cloud written out does not read back silently as an empty mesh.
  const TriMesh m = printableTetrahedron();
  const std::string text = writeObj(m.V, Triangles(0, 3));
  EXPECT_EQ(text.find("f "), std::string::npos);
  try {
    readObj(text);
    FAIL() << "a file without faces must be refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "obj.no-faces");
  }
}
