#include "io/stl_reader.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "util/error.hpp"
#include "util/text.hpp"

namespace billow {

namespace {

constexpr size_t kHeaderBytes = 84;
constexpr size_t kTriangleBytes = 50;

// known: the file's count is its header's (binary), not only as many as read so far (ASCII).
void checkTriangleLimit(std::uint64_t triangles, const MeshReadOptions& options, bool known) {
  if (triangles > static_cast<std::uint64_t>(options.maxTriangles))
    throw meshTooLarge("STL", "triangles", options.maxTriangles, known ? static_cast<long long>(triangles) : -1);
}

std::uint32_t u32le(const unsigned char* p) {
  return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[3]} << 24;
}

float f32le(const unsigned char* p) {
  const std::uint32_t bits = u32le(p);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// Text starting with "solid" and free of control bytes in its first bytes: binary files (even those whose
// header starts with "solid") have zero bytes in the triangle count or the data.
bool looksAscii(std::string_view bytes) {
  size_t start = bytes.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos || bytes.substr(start, 5) != "solid") return false;
  const std::string_view head = bytes.substr(0, 512);
  for (const char ch : head) {
    const auto c = static_cast<unsigned char>(ch);
    if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v') || c == 0x7f) return false;
  }
  return true;
}

std::uint64_t declaredCount(std::string_view bytes) {
  return u32le(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
}

bool sizeMatchesCount(std::string_view bytes) {
  return bytes.size() >= kHeaderBytes && kHeaderBytes + kTriangleBytes * declaredCount(bytes) == bytes.size();
}

[[noreturn]] void failBinarySize(std::string_view bytes) {
  if (bytes.size() < kHeaderBytes)
    throw Error("stl.truncated", "The STL file is only " + plural(bytes.size(), "byte") +
                                     " long, too short for the 84-byte header of a binary STL file, and it is "
                                     "not an ASCII STL file either (those begin with 'solid').");
  const std::uint64_t expected = declaredCount(bytes);
  const std::uint64_t found = (bytes.size() - kHeaderBytes) / kTriangleBytes;
  const std::string size = std::to_string(bytes.size());
  if (found < expected)
    throw Error("stl.truncated", "The binary STL file is cut off: its header announces " +
                                     plural(expected, "triangle") + " but its " + size + " bytes hold only " +
                                     std::to_string(found) + ". Export or download it again.");
  throw Error("stl.bad-count", "The binary STL file's header announces " + plural(expected, "triangle") + " (" +
                                   std::to_string(kHeaderBytes + kTriangleBytes * expected) +
                                   " bytes), but the file is " + size + " bytes long, room for " +
                                   std::to_string(found) + ". The file is damaged; export it again.");
}

Vertices readBinary(std::string_view bytes, const MeshReadOptions& options) {
  const std::uint64_t count = declaredCount(bytes);
  checkTriangleLimit(count, options, true);
  Vertices soup(static_cast<Eigen::Index>(3 * count), 3);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data()) + kHeaderBytes;
  for (std::uint64_t t = 0; t < count; ++t) {
    const unsigned char* corners = data + t * kTriangleBytes + 12;  // after the facet normal
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) soup(static_cast<Eigen::Index>(3 * t + c), k) = f32le(corners + 12 * c + 4 * k);
  }
  return soup;
}

// Whitespace-separated words of an ASCII STL file, with line numbers for messages.
class Words {
 public:
  explicit Words(std::string_view s) : s_(s) {}

  bool atEnd() {
    skipSpace();
    return pos_ >= s_.size();
  }
  std::string_view next() {
    skipSpace();
    const size_t start = pos_;
    while (pos_ < s_.size() && !isSpace(s_[pos_])) ++pos_;
    return s_.substr(start, pos_ - start);
  }
  void skipLine() {
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
  }
  void expect(std::string_view keyword) {
    if (atEnd()) failTruncated(keyword);
    const std::string_view w = next();
    if (!sameKeyword(w, keyword))
      fail("'" + std::string(w) + "' is not what an STL file has here (expected '" + std::string(keyword) + "')");
  }
  double number() {
    if (atEnd()) failTruncated("a coordinate");
    const std::string w(next());
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);  // "nan" and "inf" are read, for validation to report
    if (end != w.c_str() + w.size()) fail("'" + w + "' is not a number");
    return v;
  }
  static bool sameKeyword(std::string_view w, std::string_view keyword) {
    if (w.size() != keyword.size()) return false;
    for (size_t i = 0; i < w.size(); ++i)
      if ((w[i] | 0x20) != keyword[i]) return false;  // keywords are lower-case letters
    return true;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw Error("stl.syntax", "The ASCII STL file is malformed at line " + std::to_string(line_) + ": " + what + ".");
  }
  [[noreturn]] void failTruncated(std::string_view expected) const {
    throw Error("stl.truncated", "The ASCII STL file ends in the middle of a facet, at line " + std::to_string(line_) +
                                     " (expected '" + std::string(expected) +
                                     "'). The file was probably cut off; export it again.");
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
  void skipSpace() {
    for (; pos_ < s_.size() && isSpace(s_[pos_]); ++pos_)
      if (s_[pos_] == '\n') ++line_;
  }
  std::string_view s_;
  size_t pos_ = 0;
  long long line_ = 1;
};

void readFacet(Words& words, std::vector<double>& coords) {
  words.expect("normal");
  for (int k = 0; k < 3; ++k) words.number();
  words.expect("outer");
  words.expect("loop");
  for (int c = 0; c < 3; ++c) {
    words.expect("vertex");
    for (int k = 0; k < 3; ++k) coords.push_back(words.number());
  }
  words.expect("endloop");
  words.expect("endfacet");
}

// solid NAME, facets, endsolid NAME; several solids may follow each other. A missing final endsolid is
// forgiven when the last facet is complete.
Vertices readAscii(std::string_view text, const MeshReadOptions& options) {
  Words words(text);
  std::vector<double> coords;
  while (!words.atEnd()) {
    words.expect("solid");
    words.skipLine();  // the solid's name
    while (!words.atEnd()) {
      const std::string_view w = words.next();
      if (Words::sameKeyword(w, "endsolid")) {
        words.skipLine();
        break;
      }
      if (!Words::sameKeyword(w, "facet"))
        words.fail("'" + std::string(w) + "' is not what an STL file has here (expected 'facet' or 'endsolid')");
      checkTriangleLimit(coords.size() / 9 + 1, options, false);
      readFacet(words, coords);
    }
  }
  return Eigen::Map<const Vertices>(coords.data(), static_cast<Eigen::Index>(coords.size() / 3), 3);
}

}  // namespace

Vertices readStlSoup(std::string_view bytes, const MeshReadOptions& options) {
  std::string_view text = bytes;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 mark some editors write
  Vertices soup;
  if (sizeMatchesCount(bytes))
    soup = readBinary(bytes, options);
  else if (looksAscii(text))
    soup = readAscii(text, options);
  else
    failBinarySize(bytes);
  if (soup.rows() == 0)
    throw Error("stl.no-faces", "The STL file contains no triangles, so there is no surface to use.");
  return soup;
}

TriMesh readStl(std::string_view bytes, const MeshReadOptions& options, const WeldOptions& weldOptions) {
  TriMesh mesh = weld(readStlSoup(bytes, options), weldOptions);
  if (mesh.numVertices() > options.maxVertices)
    throw meshTooLarge("STL", "distinct vertices", options.maxVertices, mesh.numVertices());
  return mesh;
}

}  // namespace billow
