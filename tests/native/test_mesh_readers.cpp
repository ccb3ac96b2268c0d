// STL, PLY and OFF readers and welding: meshes are written to bytes here, in every format, and read back.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "io/mesh_file.hpp"
#include "io/off_reader.hpp"
#include "io/ply_reader.hpp"
#include "io/stl_reader.hpp"
#include "mesh/weld.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace billow;

// Outside the anonymous namespace: the parameter of a test fixture class.
enum class PlyFormat { Ascii, LittleEndian, BigEndian };

namespace {

TriMesh tetrahedron() {
  TriMesh m;
  m.V.resize(4, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.F.resize(4, 3);
  m.F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  return m;
}

// ---- byte writers -------------------------------------------------------------------------------------

void putBits(std::string& out, std::uint64_t bits, int bytes, bool bigEndian) {
  for (int i = 0; i < bytes; ++i) out += static_cast<char>(bits >> (8 * (bigEndian ? bytes - 1 - i : i)) & 0xff);
}
void putF32(std::string& out, double v, bool bigEndian = false) {
  const float f = static_cast<float>(v);
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  putBits(out, bits, 4, bigEndian);
}
void putF64(std::string& out, double v, bool bigEndian) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, 8);
  putBits(out, bits, 8, bigEndian);
}

std::string stlBinary(const TriMesh& m, const std::string& header = "billow test") {
  std::string out = header;
  out.resize(80, ' ');
  putBits(out, static_cast<std::uint64_t>(m.numTriangles()), 4, false);
  for (int t = 0; t < m.numTriangles(); ++t) {
    for (int k = 0; k < 3; ++k) putF32(out, 0.0);  // normal
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) putF32(out, m.V(m.F(t, c), k));
    out += std::string(2, '\0');  // attribute byte count
  }
  return out;
}

std::string stlAscii(const TriMesh& m) {
  std::ostringstream out;
  out.precision(17);
  out << "solid test\n";
  for (int t = 0; t < m.numTriangles(); ++t) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (int c = 0; c < 3; ++c)
      out << "      vertex " << m.V(m.F(t, c), 0) << ' ' << m.V(m.F(t, c), 1) << ' ' << m.V(m.F(t, c), 2) << '\n';
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid test\n";
  return out.str();
}

// A PLY file's first two lines, in `format`.
std::string plyStart(PlyFormat format) {
  static const char* names[] = {"ascii", "binary_little_endian", "binary_big_endian"};
  return std::string("ply\nformat ") + names[static_cast<int>(format)] + " 1.0\n";
}

// With extras: vertex normals and uchar colours, an 'edge' element between vertices and faces, a face flag
// after the index list, and a trailing 'material' element with a list.
std::string ply(const TriMesh& m, PlyFormat format, bool extras) {
  const bool binary = format != PlyFormat::Ascii, big = format == PlyFormat::BigEndian;
  std::ostringstream head;
  head << plyStart(format) << "comment written by the Billow tests\nelement vertex " << m.numVertices() << "\n";
  head << (extras
               ? "property float nx\nproperty double x\nproperty float32 y\nproperty float64 z\n"
                 "property float ny\nproperty float nz\nproperty uchar red\nproperty uint8 green\nproperty char blue\n"
               : "property double x\nproperty double y\nproperty double z\n");
  if (extras) head << "element edge 2\nproperty int vertex1\nproperty int32 vertex2\n";
  head << "element face " << m.numTriangles() << "\nproperty list uchar " << (extras ? "uint" : "int")
       << " vertex_indices\n"
       << (extras ? "property ushort flags\nelement material 1\nproperty list ushort short ids\n" : "")
       << "end_header\n";
  std::string out = head.str();
  std::ostringstream text;
  text.precision(17);
  auto num = [&](double v, int bytes) {
    if (!binary)
      text << v << ' ';
    else if (bytes == 8)
      putF64(out, v, big);
    else if (bytes == 4 && std::floor(v) != v)
      putF32(out, v, big);
    else
      putBits(out, static_cast<std::uint64_t>(static_cast<std::int64_t>(v)), bytes, big);
  };
  for (int i = 0; i < m.numVertices(); ++i) {
    if (extras) {
      num(0.5, 4), num(m.V(i, 0), 8), binary ? putF32(out, m.V(i, 1), big) : void(text << m.V(i, 1) << ' ');
      num(m.V(i, 2), 8), num(0.25, 4), num(-0.75, 4), num(200, 1), num(17, 1), num(-3, 1);
    } else {
      num(m.V(i, 0), 8), num(m.V(i, 1), 8), num(m.V(i, 2), 8);
    }
    text << '\n';
  }
  if (extras) num(0, 4), num(1, 4), text << '\n', num(2, 4), num(3, 4), text << '\n';
  for (int t = 0; t < m.numTriangles(); ++t) {
    num(3, 1), num(m.F(t, 0), 4), num(m.F(t, 1), 4), num(m.F(t, 2), 4);
    if (extras) num(7, 2);
    text << '\n';
  }
  if (extras) num(2, 2), num(-1, 2), num(5, 2), text << '\n';
  return binary ? out : out + text.str();
}

// ---- checks -------------------------------------------------------------------------------------------

// Same triangles, in the same order, over the same points (up to tol).
void expectSameMesh(const TriMesh& read, const TriMesh& original, double tol) {
  ASSERT_EQ(read.numVertices(), original.numVertices());
  ASSERT_EQ(read.numTriangles(), original.numTriangles());
  for (int t = 0; t < original.numTriangles(); ++t)
    for (int c = 0; c < 3; ++c)
      ASSERT_LE((read.V.row(read.F(t, c)) - original.V.row(original.F(t, c))).norm(), tol) << "triangle " << t;
}

void expectError(const std::function<void()>& f, const std::string& code, const std::string& inMessage = "") {
  try {
    f();
    ADD_FAILURE() << "expected billow::Error " << code;
  } catch (const Error& e) {
    EXPECT_EQ(e.code, code) << e.what();
    EXPECT_NE(std::string(e.what()).find(inMessage), std::string::npos) << e.what();
  }
}

}  // namespace

// ---- weld ---------------------------------------------------------------------------------------------

TEST(Weld, MergesEqualCornersKeepingFirstSeenOrder) {
  Vertices soup(6, 3);
  soup << 5, 0, 0, 0, 0, 0, 0, 1, 0,    //
      0, 1, 0, -0.0, 0, -0.0, 1, 0, 0;  // -0.0 equals 0.0
  WeldOptions exact;
  exact.relativeTolerance = 0;
  for (const WeldOptions& options : {WeldOptions{}, exact}) {
    const TriMesh m = weld(soup, options);
    ASSERT_EQ(m.numVertices(), 4);
    EXPECT_EQ(m.V.row(0), Eigen::RowVector3d(5, 0, 0));
    EXPECT_EQ(m.V.row(3), Eigen::RowVector3d(1, 0, 0));
    EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(0, 1, 2));
    EXPECT_EQ(m.F.row(1), Eigen::RowVector3i(2, 1, 3));
  }
}

TEST(Weld, MergesWithinRelativeToleranceOnly) {
  Vertices soup(6, 3);
  soup << 0, 0, 0, 1, 0, 0, 0, 1, 0,  //
      1e-12, 0, 0, 1, 1e-6, 0, 0, 1, -1e-12;
  const TriMesh m = weld(soup);  // diagonal ~1.4: 1e-12 merges, 1e-6 does not
  ASSERT_EQ(m.numVertices(), 4);
  EXPECT_EQ(m.F.row(1), Eigen::RowVector3i(0, 3, 2));
  EXPECT_EQ(m.V(2, 2), 0.0);  // the first occurrence's coordinates
  WeldOptions exact;
  exact.relativeTolerance = 0;
  EXPECT_EQ(weld(soup, exact).numVertices(), 6);
  WeldOptions loose;
  loose.relativeTolerance = 1e-5;
  EXPECT_EQ(weld(soup, loose).numVertices(), 3);
}

TEST(Weld, MergesAcrossGridCellsAndFarFromTheOrigin) {
  // Points straddling cell boundaries in every direction, in a box far from the origin.
  Vertices soup(6, 3);
  const double o = 1e6, d = 1e-4;                     // diagonal ~1.7e6 * 1e-9 = 1.7e-3 tolerance
  soup << o, o, o, o + 1, o, o, o, o + 1e6, o + 1e6,  //
      o + d, o - d, o + d, o + 1 - d, o + d, o - d, o + d, o + 1e6 - d, o + 1e6 + d;
  EXPECT_EQ(weld(soup).numVertices(), 3);
}

// Bounding box [0,1]^3 and tolerance t = 0.01 (grid cells 2t wide from the origin): the corners below sit
// on both sides of cell boundaries.
TEST(Weld, LooksIntoNeighbouringCellsAndJoinsTheEarliestPoint) {
  const double t = 0.01, e = 1e-3;
  WeldOptions options;
  options.relativeTolerance = t / std::sqrt(3.0);
  Vertices soup(6, 3);
  soup << 0, 0, 0, 1, 1, 1, 2 * t - e, 2 * t - e, 2 * t - e,    // just below the corner of cell (1,1,1)
      2 * t + e, 2 * t + e, 2 * t + e, 0.5, 0.5, 0.5, 1, 0, 0;  // just above it: 0.0035 away, merges
  EXPECT_EQ(weld(soup, options).F(1, 0), 2);
  // A and B are kept (1.05t apart); C is within t of both, in A's cell: it joins A, the earlier one.
  soup << 0, 0, 0, 1, 1, 1, t, 0.5, 0.5,               // A
      2.05 * t, 0.5, 0.5, 1.9 * t, 0.5, 0.5, 1, 0, 0;  // B, C
  const TriMesh m = weld(soup, options);
  EXPECT_EQ(m.numVertices(), 5);
  EXPECT_EQ(m.F(1, 1), 2);
}

TEST(Weld, LeavesNonFiniteCornersAloneAndRejectsPartialTriangles) {
  Vertices soup(6, 3);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  soup << 0, 0, 0, 1, 0, 0, nan, 0, 0,  //
      nan, 0, 0, 1, 0, 0, inf, 0, 0;
  const TriMesh m = weld(soup);
  EXPECT_EQ(m.numVertices(), 5);
  EXPECT_EQ(m.F(1, 1), 1);
  EXPECT_TRUE(std::isnan(m.V(2, 0)));
  expectError([] { weld(Vertices::Zero(4, 3)); }, "weld.bad-soup", "4 corners");
}

TEST(Weld, RebuildsTheSharedSphereFromItsSoup) {
  const TriMesh sphere = test::loadShared("sphere.obj");
  Vertices soup(3 * sphere.numTriangles(), 3);
  for (int t = 0; t < sphere.numTriangles(); ++t)
    for (int c = 0; c < 3; ++c) soup.row(3 * t + c) = sphere.V.row(sphere.F(t, c));
  expectSameMesh(weld(soup), sphere, 0);
}

// ---- STL ----------------------------------------------------------------------------------------------

TEST(StlReader, BinaryRoundTripOfTheSphere) {
  const TriMesh sphere = test::loadShared("sphere.obj");
  const std::string bytes = stlBinary(sphere);
  EXPECT_EQ(bytes.size(), 84u + 50u * 1280u);
  expectSameMesh(readStl(bytes), sphere, 1e-6);
  expectSameMesh(readMeshBytes(bytes, "Sphere.STL"), sphere, 1e-6);
}

TEST(StlReader, AsciiRoundTripOfTheSphere) {
  const TriMesh sphere = test::loadShared("sphere.obj");
  expectSameMesh(readStl(stlAscii(sphere)), sphere, 0);
  expectSameMesh(readMeshBytes(stlAscii(sphere), "sphere.stl"), sphere, 0);
}

TEST(StlReader, BinaryWhoseHeaderStartsWithSolid) {
  const TriMesh tet = tetrahedron();
  expectSameMesh(readStl(stlBinary(tet, "solid tetrahedron exported by a CAD tool")), tet, 0);
  expectSameMesh(readStl(stlBinary(tet, "solid")), tet, 0);
}

TEST(StlReader, AsciiAcceptsUpperCaseSeveralSolidsAndAMissingEndsolid) {
  const std::string bom = "\xEF\xBB\xBF";
  EXPECT_EQ(readStl(bom + stlAscii(tetrahedron())).numTriangles(), 4);
  const std::string facet = "FACET NORMAL 0 0 1 OUTER LOOP VERTEX 0 0 0 VERTEX 1 0 0 VERTEX 0 1 0 ENDLOOP ENDFACET\n";
  const TriMesh m = readStl("solid a\n" + facet + "endsolid a\nsolid b\n" + facet);
  EXPECT_EQ(m.numTriangles(), 2);
  EXPECT_EQ(m.numVertices(), 3);
}

TEST(StlReader, LeavesNanAndInfinityToValidation) {
  const TriMesh m = readStl(
      "solid s\nfacet normal 0 0 0\nouter loop\nvertex nan 0 0\nvertex inf 0 0\n"
      "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n");
  EXPECT_TRUE(std::isnan(m.V(0, 0)));
  EXPECT_TRUE(std::isinf(m.V(1, 0)));
  TriMesh tet = tetrahedron();
  tet.V(3, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(readStl(stlBinary(tet)).V(3, 2)));
}

TEST(StlReader, TruncatedBinarySaysHowManyTrianglesWereExpectedAndFound) {
  const std::string bytes = stlBinary(test::loadShared("sphere.obj"));
  expectError([&] { readStl(bytes.substr(0, bytes.size() - 75)); }, "stl.truncated", "1280 triangles");
  expectError([&] { readStl(bytes.substr(0, bytes.size() - 75)); }, "stl.truncated", "only 1278");
  expectError([] { readStl("tiny"); }, "stl.truncated", "4 bytes");
  const std::string solid = stlBinary(tetrahedron(), "solid tetrahedron");
  expectError([&] { readStl(solid.substr(0, solid.size() - 1)); }, "stl.truncated", "only 3");
}

TEST(StlReader, CountThatDoesNotMatchTheSize) {
  const std::string bytes = stlBinary(tetrahedron());
  expectError([&] { readStl(bytes + std::string(60, '\0')); }, "stl.bad-count", "room for 5");
}

TEST(StlReader, AsciiErrorsNameTheLine) {
  const std::string good = stlAscii(tetrahedron());
  std::string bad = good;
  bad.replace(bad.find("vertex 1 0 0"), 12, "vertex 1 O 0");
  expectError([&] { readStl(bad); }, "stl.syntax", "line 6: 'O' is not a number");
  bad = good;
  bad.replace(bad.find("outer loop"), 10, "outer ring");
  expectError([&] { readStl(bad); }, "stl.syntax", "'ring'");
  bad = good;
  bad.replace(bad.find("facet normal"), 5, "facer");
  expectError([&] { readStl(bad); }, "stl.syntax", "line 2");
  expectError([&] { readStl(good.substr(0, good.find("endloop"))); }, "stl.truncated", "line 7 (expected 'endloop')");
  expectError([] { readStl("solid empty\nendsolid empty\n"); }, "stl.no-faces");
}

TEST(StlReader, RefusesMeshesBeyondTheLimits) {
  MeshReadOptions fewTriangles;
  fewTriangles.maxTriangles = 3;
  expectError([&] { readStl(stlBinary(tetrahedron()), fewTriangles); }, "mesh.too-large");
  expectError([&] { readStl(stlAscii(tetrahedron()), fewTriangles); }, "mesh.too-large");
  MeshReadOptions fewVertices;
  fewVertices.maxVertices = 3;
  expectError([&] { readStl(stlBinary(tetrahedron()), fewVertices); }, "mesh.too-large", "4 distinct vertices");
  EXPECT_EQ(readStl(stlBinary(tetrahedron()), MeshReadOptions{4, 4}).numVertices(), 4);
}

// ---- PLY ----------------------------------------------------------------------------------------------

class PlyRoundTrip : public ::testing::TestWithParam<PlyFormat> {};

TEST_P(PlyRoundTrip, SphereReadsBackExactly) {
  const TriMesh sphere = test::loadShared("sphere.obj");
  const std::string bytes = ply(sphere, GetParam(), false);
  expectSameMesh(readPly(bytes), sphere, 0);
  EXPECT_EQ(readPly(bytes).V, sphere.V);
  expectSameMesh(readMeshBytes(bytes, "sphere.PLY"), sphere, 0);
}

TEST_P(PlyRoundTrip, SkipsExtraPropertiesAndElements) {
  const TriMesh sphere = test::loadShared("sphere.obj");
  const TriMesh m = readPly(ply(sphere, GetParam(), true));
  EXPECT_EQ(m.F, sphere.F);
  EXPECT_EQ(m.V.col(0), sphere.V.col(0));  // x and z are doubles, y a float
  EXPECT_EQ(m.V.col(2), sphere.V.col(2));
  EXPECT_LE((m.V.col(1) - sphere.V.col(1)).cwiseAbs().maxCoeff(), 1e-6);
}

TEST_P(PlyRoundTrip, TruncatedBodyNamesTheElement) {
  const std::string bytes = ply(tetrahedron(), GetParam(), true);
  const size_t cut = bytes.size() - (GetParam() == PlyFormat::Ascii ? 14 : 12);  // into face 3
  expectError([&] { readPly(bytes.substr(0, cut)); }, "ply.truncated", "face 3");
}

static std::string formatName(const ::testing::TestParamInfo<PlyFormat>& info) {
  static const char* names[] = {"Ascii", "BinaryLittleEndian", "BinaryBigEndian"};
  return names[static_cast<int>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(Formats, PlyRoundTrip,
                         ::testing::Values(PlyFormat::Ascii, PlyFormat::LittleEndian, PlyFormat::BigEndian),
                         formatName);

static const char* kSquareHeader =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_index\nend_header\n";

TEST(PlyReader, SplitsPolygonsIntoFans) {
  const TriMesh m = readPly(std::string(kSquareHeader) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  ASSERT_EQ(m.numTriangles(), 2);
  EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(m.F.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(m.V(2, 1), 1.0);
}

// The vertices (x, y, z as doubles) and one 'tristrips' element whose int list is `strip` (-1 ends a strip).
std::string plyStrips(const Eigen::MatrixXd& V, const std::vector<int>& strip, PlyFormat format) {
  const bool binary = format != PlyFormat::Ascii, big = format == PlyFormat::BigEndian;
  std::ostringstream head;
  head << plyStart(format) << "element vertex " << V.rows()
       << "\nproperty double x\nproperty double y\nproperty double z\n"
       << "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
  std::string out = head.str();
  std::ostringstream text;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    for (int k = 0; k < 3; ++k) binary ? putF64(out, V(i, k), big) : void(text << V(i, k) << (k == 2 ? "\n" : " "));
  if (binary) {
    putBits(out, strip.size(), 4, big);
    for (int v : strip) putBits(out, static_cast<std::uint64_t>(static_cast<std::int64_t>(v)), 4, big);
    return out;
  }
  text << strip.size();
  for (int v : strip) text << ' ' << v;
  return out + text.str() + "\n";
}

// A triangle's corners turned so that the smallest comes first (the same triangle, facing the same way).
Eigen::RowVector3i rotatedToSmallest(const Eigen::RowVector3i& t) {
  int k = 0;
  for (int c = 1; c < 3; ++c)
    if (t(c) < t(k)) k = c;
  return {t(k), t((k + 1) % 3), t((k + 2) % 3)};
}

TEST_P(PlyRoundTrip, TriangleStripsFaceOneWayAndEndAtMinusOne) {
  // One strip around a tetrahedron gives its four faces, each facing out as the faces the other readers get.
  const TriMesh tet = tetrahedron();
  const TriMesh fromStrip = readPly(plyStrips(tet.V, {0, 2, 1, 3, 0, 2}, GetParam()));
  ASSERT_EQ(fromStrip.numTriangles(), 4);
  std::vector<std::array<int, 3>> got, expected;
  for (int t = 0; t < 4; ++t) {
    const Eigen::RowVector3i a = rotatedToSmallest(fromStrip.F.row(t)), b = rotatedToSmallest(tet.F.row(t));
    got.push_back({a(0), a(1), a(2)}), expected.push_back({b(0), b(1), b(2)});
  }
  std::sort(got.begin(), got.end()), std::sort(expected.begin(), expected.end());
  EXPECT_EQ(got, expected);
  // Two ladders in the plane, the second after a -1, and a repeated vertex: every triangle faces -z, none spans
  // the restart, and the ones with a repeated corner are left out.
  Eigen::MatrixXd V(10, 3);
  for (int i = 0; i < 10; ++i) V.row(i) << i / 2 + (i >= 6 ? 1 : 0), i % 2, 0;
  const TriMesh ladders = readPly(plyStrips(V, {0, 1, 2, 3, 4, 5, -1, 6, 7, 8, 8, 9}, GetParam()));
  ASSERT_EQ(ladders.numTriangles(), 5);  // 4 in the first; 6-7-8 in the second (7-8-8 and 8-8-9 repeat a corner)
  for (int t = 0; t < ladders.numTriangles(); ++t) {
    const Eigen::Vector3d a = ladders.V.row(ladders.F(t, 0)), b = ladders.V.row(ladders.F(t, 1)),
                          c = ladders.V.row(ladders.F(t, 2));
    EXPECT_LT((b - a).cross(c - a).z(), 0) << "triangle " << t;
    EXPECT_FALSE((ladders.F.row(t).array() <= 5).any() && (ladders.F.row(t).array() >= 6).any()) << "triangle " << t;
  }
  expectError([&] { readPly(plyStrips(V, {0, 1, 12}, GetParam())); }, "ply.bad-index", "strips");
}

TEST(PlyReader, ReadsSignedIntegerCoordinatesInBothByteOrders) {
  for (const bool big : {false, true}) {
    std::string b = std::string("ply\nformat binary_") + (big ? "big" : "little") +
                    "_endian 1.0\nelement vertex 3\nproperty char x\nproperty short y\nproperty int32 z\n"
                    "element face 1\nproperty list uint8 ushort vertex_indices\nend_header\n";
    const int v[3][3] = {{-3, -300, -70000}, {100, 20000, 5}, {0, -1, 2000000000}};
    for (const auto& p : v)
      putBits(b, static_cast<std::uint64_t>(p[0]), 1, big), putBits(b, static_cast<std::uint64_t>(p[1]), 2, big),
          putBits(b, static_cast<std::uint64_t>(p[2]), 4, big);
    putBits(b, 3, 1, big), putBits(b, 2, 2, big), putBits(b, 0, 2, big), putBits(b, 1, 2, big);
    const TriMesh m = readPly(b);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(m.V.row(i), Eigen::RowVector3d(v[i][0], v[i][1], v[i][2])) << i;
    EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(2, 0, 1));
  }
}

TEST(PlyReader, HeaderErrors) {
  const std::string body = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  const std::string header = kSquareHeader;
  auto with = [&](const std::string& from, const std::string& to) {
    std::string h = header;
    return h.replace(h.find(from), from.size(), to) + body;
  };
  expectError([&] { readPly(header.substr(0, header.find("end_header"))); }, "ply.no-header-end");
  expectError([&] { readPly(with("ascii", "binary_middle_endian")); }, "ply.unsupported-format", "middle");
  expectError([&] { readPly(with("property float y", "property float w")); }, "ply.missing-coordinates", "'y'");
  expectError([&] { readPly(with("vertex_index", "corners")); }, "ply.missing-indices");
  expectError([&] { readPly(with("float z", "quad z")); }, "ply.bad-header", "line 6");
  expectError([&] { readPly(with("ply\n", "obj\n")); }, "ply.not-ply");
  expectError([&] { readPly(with("element face 1", "element face 0")); }, "ply.no-faces");
}

TEST(PlyReader, BodyErrors) {
  const std::string header = kSquareHeader;
  expectError([&] { readPly(header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 4\n"); }, "ply.bad-index",
              "Face 0 of the PLY file refers to vertex 4");
  expectError([&] { readPly(header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 -1 2\n"); }, "ply.bad-index", "vertex -1");
  std::string none = header;
  none.replace(none.find("vertex 4"), 8, "vertex 0");
  expectError([&] { readPly(none + "3 0 1 2\n"); }, "ply.bad-index", "the file has no vertices");
  expectError([&] { readPly(header + "0 0 0\n1 0 0\n1 one 0\n0 1 0\n4 0 1 2 3\n"); }, "ply.syntax",
              "vertex 2 (line 12): 'one'");
  expectError([&] { readPly(header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 1\n"); }, "ply.bad-face", "face 0");
}

TEST(PlyReader, AbsurdCountsAreRefusedBeforeAllocating) {
  std::string h = kSquareHeader;
  h.replace(h.find("vertex 4"), 8, "vertex 4000000000");
  expectError([&] { readPly(h + "0 0 0\n"); }, "ply.bad-count", "4000000000");
  std::string b = ply(tetrahedron(), PlyFormat::LittleEndian, false);
  b.replace(b.find("face 4"), 6, "face 9");  // a face takes at least 1 byte: cut off, not absurd
  expectError([&] { readPly(b); }, "ply.truncated", "face 4");
  b.replace(b.find("face 9"), 6, "face 99999");
  expectError([&] { readPly(b); }, "ply.bad-count", "99999 elements 'face'");
}

TEST(PlyReader, RefusesMeshesBeyondTheLimits) {
  const std::string bytes = ply(tetrahedron(), PlyFormat::LittleEndian, false);
  expectError([&] { readPly(bytes, MeshReadOptions{3, 10}); }, "mesh.too-large", "4 vertices");
  expectError([&] { readPly(bytes, MeshReadOptions{10, 3}); }, "mesh.too-large", "more than 3 triangles");
  const std::string square = std::string(kSquareHeader) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  expectError([&] { readPly(square, MeshReadOptions{10, 1}); }, "mesh.too-large", "more than 1 triangles");
  EXPECT_EQ(readPly(bytes, MeshReadOptions{4, 4}).numTriangles(), 4);
}

// ---- dispatch -----------------------------------------------------------------------------------------

TEST(MeshFile, UnknownFormatListsTheReadableOnes) {
  expectError([] { readMeshBytes("", "model.fbx"); }, "io.unknown-format", "OBJ, STL, PLY or OFF");
  expectError([] { readMeshBytes("solid x\nendsolid x\n", "x.Stl"); }, "stl.no-faces");
  expectError([] { readMeshBytes("ply\n", "x.pLy"); }, "ply.no-header-end");
}

// An empty file (a download or a copy that went wrong) says so in every format, not that a header or faces are missing.
TEST(MeshFile, AnEmptyFileSaysSo) {
  for (const char* name : {"model.obj", "model.STL", "model.ply", "model.off"})
    expectError([&] { readMeshBytes("", name); }, "mesh.empty-file", std::string("\"") + name + "\" is empty");
}

// An OBJ or PLY written a vertex per face corner (as some exporters do) reads as the same mesh as one whose faces share
// their vertices, as an STL does: the one reader welds every format alike. Unused vertices go; the faces keep their
// order.
TEST(MeshFile, EveryFormatIsWeldedAlike) {
  const TriMesh shared = tetrahedron();
  TriMesh perCorner;
  perCorner.V.resize(3 * shared.numTriangles() + 1, 3);
  perCorner.F.resize(shared.numTriangles(), 3);
  for (int t = 0; t < shared.numTriangles(); ++t)
    for (int c = 0; c < 3; ++c) {
      perCorner.V.row(3 * t + c) = shared.V.row(shared.F(t, c)) + Eigen::RowVector3d(1e-9, 0, 0) * c;
      perCorner.F(t, c) = 3 * t + c;
    }
  perCorner.V.row(3 * shared.numTriangles()) << 5, 5, 5;  // used by no face
  std::ostringstream obj;
  for (int v = 0; v < perCorner.numVertices(); ++v)
    obj << "v " << perCorner.V(v, 0) << ' ' << perCorner.V(v, 1) << ' ' << perCorner.V(v, 2) << '\n';
  for (int t = 0; t < perCorner.numTriangles(); ++t)
    obj << "f " << perCorner.F(t, 0) + 1 << ' ' << perCorner.F(t, 1) + 1 << ' ' << perCorner.F(t, 2) + 1 << '\n';
  const TriMesh fromStl = readMeshBytes(stlBinary(shared), "a.stl");
  for (const TriMesh& read :
       {readMeshBytes(obj.str(), "a.obj"), readMeshBytes(ply(perCorner, PlyFormat::LittleEndian, false), "a.ply")}) {
    EXPECT_EQ(read.numVertices(), 4);
    EXPECT_EQ(read.F, fromStl.F);
    expectSameMesh(read, shared, 1e-6);
  }
  // Faces that already share their vertices keep them, in the order the faces first use them.
  const TriMesh again = readMeshBytes(ply(shared, PlyFormat::Ascii, false), "b.ply");
  EXPECT_EQ(again.F, fromStl.F);
}

// ---- OFF ----------------------------------------------------------------------------------------------

namespace {

// m as OFF text: the header alone on its line ("OFF"), on the counts' line ("OFF 8 6 0") or left out (""), with
// a colour after each vertex and face when the header says COFF, and comments between.
std::string off(const TriMesh& m, const std::string& header, bool countsOnHeaderLine = false) {
  std::ostringstream s;
  s.precision(17);
  s << "# written by the test\n";
  if (!header.empty()) s << header << (countsOnHeaderLine ? " " : "\n");
  s << m.numVertices() << ' ' << m.numTriangles() << " 0\n\n";
  const bool colours = header == "COFF";
  for (int v = 0; v < m.numVertices(); ++v) {
    s << m.V(v, 0) << ' ' << m.V(v, 1) << '\t' << m.V(v, 2);
    if (colours) s << " 255 128 0 255";
    s << (v == 0 ? "  # the first vertex\r\n" : "\n");
  }
  for (int t = 0; t < m.numTriangles(); ++t) {
    s << "3 " << m.F(t, 0) << ' ' << m.F(t, 1) << ' ' << m.F(t, 2);
    if (colours) s << " 0.5 0.5 0.5";
    s << '\n';
  }
  return s.str();
}

const char* const kSquareOff = "OFF\n4 1 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

}  // namespace

TEST(OffReader, SphereReadsBackExactlyWhateverItsHeader) {
  const TriMesh sphere = test::loadShared("sphere.obj");
  for (const auto& [header, sameLine] : std::vector<std::pair<std::string, bool>>{
           {"OFF", false}, {"OFF", true}, {"", false}, {"COFF", false}, {"NOFF", false}}) {
    SCOPED_TRACE(header + (sameLine ? " (counts on its line)" : ""));
    expectSameMesh(readMeshBytes(off(sphere, header, sameLine), "sphere.OFF"), sphere, 0);
  }
}

TEST(OffReader, SplitsPolygonsIntoFansAndSkipsWhatFollowsTheFaces) {
  const TriMesh m = readOff(std::string(kSquareOff) + "4 0 1 2 3\n0 1\n1 2\n");
  ASSERT_EQ(m.numTriangles(), 2);
  EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(m.F.row(1), Eigen::RowVector3i(0, 2, 3));
}

TEST(OffReader, ErrorsNameTheLineAndWhatToDo) {
  const std::string square = kSquareOff;
  expectError([&] { readOff(square + "3 0 1 4\n"); }, "off.syntax", "line 7: vertex 4 does not exist");
  expectError([&] { readOff(square + "3 0 -1 2\n"); }, "off.syntax", "vertex -1 does not exist");
  expectError([&] { readOff(square + "2 0 1\n"); }, "off.syntax", "at least three vertices");
  expectError([&] { readOff(square + "4 0 1 2\n"); }, "off.syntax", "names 3 of its 4 vertices");
  expectError([&] { readOff("OFF\n4 1 4\n0 0 0\n1 zero 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"); }, "off.syntax",
              "line 4: 'zero' is not a number");
  expectError([&] { readOff("OFF\n4 1 4\n0 0 0\n1 0\n"); }, "off.syntax", "line 4: a vertex needs three coordinates");
  expectError([&] { readOff("OFF\n4\n"); }, "off.syntax", "numbers of vertices and faces");
  expectError([&] { readOff("OFF\n"); }, "off.syntax", "numbers of vertices and faces are missing");
  expectError([&] { readOff("OFF\n4 1 4\n0 0 0\n1 0 0\n"); }, "off.truncated", "after 2 vertices of the 4");
  expectError([&] { readOff(square + "# no face\n"); }, "off.truncated", "after 0 faces of the 1");
  expectError([&] { readOff("OFF\n4 0 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"); }, "off.no-faces");
  expectError([&] { readOff("# nothing\n\n"); }, "off.no-faces", "empty");
  expectError([&] { readOff("OFF BINARY\n\x01\x02"); }, "off.unsupported-format", "Save it as text OFF");
  expectError([&] { readOff("4OFF\n1 1 0\n0 0 0 1\n"); }, "off.unsupported-format", "'4OFF'");
  expectError([&] { readMeshBytes("OFF\n1 1 0\n", "mesh.off3"); }, "io.unknown-format", "OFF format");
}

TEST(OffReader, RefusesMeshesBeyondTheLimitsBeforeReadingThem) {
  MeshReadOptions small;
  small.maxVertices = 3;
  expectError([&] { readOff(kSquareOff, small); }, "mesh.too-large", "4 vertices");
  small = {};
  small.maxTriangles = 1;
  expectError([&] { readOff(std::string(kSquareOff) + "4 0 1 2 3\n", small); }, "mesh.too-large", "OFF file");
  // An absurd count in a small file is a file cut off, found without reserving memory for the count.
  expectError([&] { readOff("OFF\n4000000 1 0\n0 0 0\n"); }, "off.truncated", "after 1 vertex of the 4,000,000");
}

TEST(MeshFile, EveryReaderWordsItsLimitsAlike) {
  // One message for a mesh too large, whichever reader finds it: the count where the file says it, the limit, and
  // what to do (util/text.hpp's tooLargeMessage).
  const std::string advice =
      " Billow can work with. Simplify it (for example with Decimate in Blender or MeshLab) and open it again.";
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const std::string off = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::vector<std::pair<std::string, std::string>> files = {
      {"tetrahedron.obj", obj},
      {"tetrahedron.off", off},
      {"tetrahedron.stl", stlBinary(tetrahedron())},
      {"tetrahedron.ply", ply(tetrahedron(), PlyFormat::Ascii, false)}};
  for (const auto& [name, bytes] : files)
    for (const MeshReadOptions limits : {MeshReadOptions{3, 10}, MeshReadOptions{10, 3}}) {
      try {
        readMeshBytes(bytes, name, limits);
        ADD_FAILURE() << name << ": read past its limits";
      } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(e.code, "mesh.too-large") << message;
        EXPECT_NE(message.find(" 3 "), std::string::npos) << message;
        EXPECT_NE(message.find(limits.maxVertices == 3 ? "vertices" : "triangles"), std::string::npos) << message;
        ASSERT_GE(message.size(), advice.size());
        EXPECT_EQ(message.substr(message.size() - advice.size()), advice) << name;
      }
    }
}
