// Inputs found by the libFuzzer targets (tests/fuzz, scripts/fuzz.sh) that once escaped as something other
// than billow::Error. Each input is also kept in tests/fuzz/corpus/<target>/.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/design_json.hpp"
#include "io/off_reader.hpp"
#include "io/pattern_json.hpp"
#include "io/ply_reader.hpp"
#include "util/error.hpp"

using namespace billow;

namespace {

// The code of the billow::Error `f` throws; "" when it returns, "other exception" for any other exception.
template <class F>
std::string errorCode(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.code;
  } catch (...) {
    return "other exception";
  }
  return "";
}

}  // namespace

// fuzz_pattern_json, corpus/pattern_json/regress_number_overflow.json: a number beyond double's range made
// nlohmann::json throw out_of_range (406), which readPatternJson let through (it caught parse_error only).
TEST(FuzzRegressions, PatternNumberOverflowIsAJsonError) {
  EXPECT_EQ(errorCode([] { readPatternJson("1e309"); }), "pattern.json");
  EXPECT_EQ(errorCode([] { readPatternJson(R"({"format": "billow-pattern", "version": 1, "pressure": -1e400})"); }),
            "pattern.json");
}

// The design reader parses without exceptions; the same input must give its own error code.
TEST(FuzzRegressions, DesignNumberOverflowIsAJsonError) {
  EXPECT_EQ(errorCode([] { readDesignJson("1e309"); }), "design.json");
  EXPECT_EQ(errorCode([] { readDesignJson(R"({"format": "billow-design", "version": 1, "pressure": 1e309})"); }),
            "design.json");
}

// fuzz_ply, corpus/ply/regress_empty_element_hang.ply: an element without properties takes no bytes, so the
// size check cannot bound its count; readPly looped over its 8.9e15 (empty) elements and hung.
TEST(FuzzRegressions, PlyElementWithoutPropertiesAndHugeCountDoesNotHang) {
  const std::string ply =
      "ply\nformat ascii 1.0\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element nothing 9000000000000000\n"
      "element face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const TriMesh mesh = readPly(ply);
  EXPECT_EQ(mesh.V.rows(), 3);
  ASSERT_EQ(mesh.F.rows(), 1);
  EXPECT_EQ(mesh.F(0, 2), 2);
  // The same in binary: the empty element sits between the vertices and the faces.
  std::string bin =
      "ply\nformat binary_little_endian 1.0\n"
      "element vertex 3\nproperty uchar x\nproperty uchar y\nproperty uchar z\n"
      "element nothing 9000000000000000\n"
      "element face 1\nproperty list uchar uchar vertex_indices\n"
      "end_header\n";
  bin += std::string("\0\0\0\1\0\0\0\1\0\3\0\1\2", 13);
  const TriMesh binMesh = readPly(bin);
  EXPECT_EQ(binMesh.V.rows(), 3);
  EXPECT_EQ(binMesh.F.rows(), 1);
}

// fuzz_off, corpus/off/regress_huge_face_count.off: a face's vertex count past a long long (strtoll saturates)
// overflowed the check of how many indices its line names (UBSan).
TEST(FuzzRegressions, OffFaceCountBeyondItsLineIsASyntaxError) {
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n99999999999999999999999 0 1 2\n";
  EXPECT_EQ(errorCode([&] { readOff(off); }), "off.syntax");
}
