#include "io/obj_reader.hpp"

#include <cerrno>
#include <cstdlib>
#include <string>
#include <vector>

#include "util/error.hpp"
#include "util/text.hpp"

namespace billow {

namespace {

class LineParser {
 public:
  LineParser(std::string_view line, long long number) : s_(line), number_(number) {}

  bool atEnd() {
    skipSpace();
    return pos_ >= s_.size() || s_[pos_] == '#';
  }
  std::string_view word() {
    skipSpace();
    const size_t start = pos_;
    while (pos_ < s_.size() && !isSpace(s_[pos_])) ++pos_;
    return s_.substr(start, pos_ - start);
  }
  double number() {
    const std::string w(word());
    if (w.empty()) fail("a coordinate is missing");
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(w.c_str(), &end);
    if (end != w.c_str() + w.size()) fail("'" + w + "' is not a number");
    return v;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw Error("obj.syntax", "The OBJ file is malformed at line " + std::to_string(number_) + ": " + what + ".");
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
  void skipSpace() {
    while (pos_ < s_.size() && isSpace(s_[pos_])) ++pos_;
  }
  std::string_view s_;
  size_t pos_ = 0;
  long long number_;
};

}  // namespace

Error meshTooLarge(const std::string& format, const std::string& what, long long limit, long long count) {
  return Error("mesh.too-large", tooLargeMessage("The " + format + " file", count, limit, what));
}

TriMesh readObj(std::string_view text, const MeshReadOptions& options) {
  std::vector<double> coords;
  std::vector<int> corners;
  std::vector<long long> polygon;
  long long lineNumber = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    LineParser line(text.substr(pos, end - pos), ++lineNumber);
    pos = end + 1;
    if (line.atEnd()) continue;
    const std::string_view kind = line.word();
    if (kind == "v") {
      if (static_cast<long long>(coords.size() / 3) >= options.maxVertices)
        throw meshTooLarge("OBJ", "vertices", options.maxVertices);
      for (int k = 0; k < 3; ++k) coords.push_back(line.number());
    } else if (kind == "f") {
      polygon.clear();
      while (!line.atEnd()) {
        const std::string corner(line.word());
        char* stop = nullptr;
        const long long index = std::strtoll(corner.c_str(), &stop, 10);
        if (stop == corner.c_str() || (*stop != '\0' && *stop != '/'))
          line.fail("'" + corner + "' is not a vertex index");
        const long long count = static_cast<long long>(coords.size() / 3);
        const long long resolved = index < 0 ? count + index : index - 1;
        if (index == 0 || resolved < 0 || resolved >= count)
          line.fail("vertex " + std::to_string(index) + " does not exist (there are " + std::to_string(count) +
                    " vertices so far)");
        polygon.push_back(resolved);
      }
      if (polygon.size() < 3) line.fail("a face needs at least three vertices");
      for (size_t k = 1; k + 1 < polygon.size(); ++k) {
        if (static_cast<long long>(corners.size() / 3) >= options.maxTriangles)
          throw meshTooLarge("OBJ", "triangles", options.maxTriangles);
        corners.push_back(static_cast<int>(polygon[0]));
        corners.push_back(static_cast<int>(polygon[k]));
        corners.push_back(static_cast<int>(polygon[k + 1]));
      }
    }
    // Other statements (vt, vn, o, g, s, usemtl, mtllib, l, ...) carry nothing a target needs.
  }
  if (corners.empty()) throw Error("obj.no-faces", "The OBJ file contains no faces, so there is no surface to use.");
  TriMesh mesh;
  mesh.V = Eigen::Map<const Vertices>(coords.data(), static_cast<Eigen::Index>(coords.size() / 3), 3);
  mesh.F = Eigen::Map<const Triangles>(corners.data(), static_cast<Eigen::Index>(corners.size() / 3), 3);
  return mesh;
}

}  // namespace billow
