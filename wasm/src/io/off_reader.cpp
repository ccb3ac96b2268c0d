#include "io/off_reader.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "util/error.hpp"
#include "util/text.hpp"

namespace billow {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The file's lines with something on them (comments and blank lines skipped), each cut into words.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}

  // The next line's words; false at the end of the file.
  bool next(std::vector<std::string_view>& words) {
    while (pos_ < text_.size()) {
      size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++number_;
      if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      words.clear();
      for (size_t i = 0; i < line.size();) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
      }
      if (!words.empty()) return true;
    }
    return false;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error("off.syntax", "The OFF file is malformed at line " + std::to_string(number_) + ": " + what + ".");
  }

  double number(std::string_view word) const {
    const std::string w(word);
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (end != w.c_str() + w.size()) fail("'" + w + "' is not a number");
    return v;
  }

  long long integer(std::string_view word, const std::string& what) const {
    const std::string w(word);
    char* end = nullptr;
    const long long v = std::strtoll(w.c_str(), &end, 10);
    if (end == w.c_str() || end != w.c_str() + w.size()) fail("'" + w + "' is not " + what);
    return v;
  }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  long long number_ = 0;
};

// A 3D OFF header: [ST][C][N]OFF (texture coordinates, colours, normals after each vertex's coordinates).
bool isHeader(std::string_view w) {
  if (w.size() < 3 || w.substr(w.size() - 3) != "OFF") return false;
  std::string_view prefix = w.substr(0, w.size() - 3);
  for (std::string_view part : {"ST", "C", "N"})
    if (prefix.substr(0, part.size()) == part) prefix.remove_prefix(part.size());
  return prefix.empty();
}

}  // namespace

TriMesh readOff(std::string_view text, const MeshReadOptions& options) {
  Lines lines(text);
  std::vector<std::string_view> w;
  if (!lines.next(w)) throw Error("off.no-faces", "The OFF file is empty, so there is no surface to use.");
  size_t first = 0;  // where the counts start on this line
  if (isHeader(w[0])) {
    if (w.size() > 1 && w[1] == "BINARY")
      throw Error("off.unsupported-format",
                  "The OFF file is binary ('" + std::string(w[0]) +
                      " BINARY'), and Billow reads OFF as text. Save it as text OFF, or as OBJ, STL or PLY.");
    if (w.size() > 1)
      first = 1;  // the counts on the header's line
    else if (!lines.next(w))
      lines.fail("the numbers of vertices and faces are missing");
  } else if (w[0].size() >= 3 && w[0].substr(w[0].size() - 3) == "OFF") {
    throw Error("off.unsupported-format", "The OFF file is of the kind '" + std::string(w[0]) +
                                              "' (not of points in 3D), which Billow cannot use as a shape. "
                                              "Save it as OFF, OBJ, STL or PLY with 3D vertices.");
  }
  if (w.size() < first + 2) lines.fail("it needs the numbers of vertices and faces, e.g. '8 6 12'");
  const long long vertices = lines.integer(w[first], "a number of vertices");
  const long long faces = lines.integer(w[first + 1], "a number of faces");
  if (vertices < 0 || faces < 0) lines.fail("the numbers of vertices and faces cannot be negative");
  if (vertices > options.maxVertices) throw meshTooLarge("OFF", "vertices", options.maxVertices, vertices);
  if (faces == 0) throw Error("off.no-faces", "The OFF file contains no faces, so there is no surface to use.");
  std::vector<double> coords;
  // Reserved for as many vertices as the file can hold (six bytes each at least), not as it announces.
  coords.reserve(3 * std::min(static_cast<size_t>(vertices), text.size() / 6 + 1));
  for (long long v = 0; v < vertices; ++v) {
    if (!lines.next(w))
      throw Error("off.truncated", "The OFF file ends after " + grouped(v) + (v == 1 ? " vertex" : " vertices") +
                                       " of the " + grouped(vertices) + " it announces; it was probably cut off.");
    if (w.size() < 3) lines.fail("a vertex needs three coordinates");
    for (int k = 0; k < 3; ++k) coords.push_back(lines.number(w[k]));
  }
  std::vector<int> corners;
  std::vector<int> polygon;
  for (long long f = 0; f < faces; ++f) {
    if (!lines.next(w))
      throw Error("off.truncated", "The OFF file ends after " + grouped(f) + (f == 1 ? " face" : " faces") +
                                       " of the " + grouped(faces) + " it announces; it was probably cut off.");
    const long long n = lines.integer(w[0], "a face's number of vertices");
    if (n < 3) lines.fail("a face needs at least three vertices");
    if (n > static_cast<long long>(w.size()) - 1)
      lines.fail("the face names " + std::to_string(w.size() - 1) + " of its " + std::to_string(n) + " vertices");
    polygon.clear();
    for (long long k = 1; k <= n; ++k) {
      const long long index = lines.integer(w[k], "a vertex index");
      if (index < 0 || index >= vertices)
        lines.fail("vertex " + std::to_string(index) + " does not exist (the vertices are numbered 0 to " +
                   std::to_string(vertices - 1) + ")");
      polygon.push_back(static_cast<int>(index));
    }
    for (size_t k = 1; k + 1 < polygon.size(); ++k) {
      if (static_cast<long long>(corners.size() / 3) >= options.maxTriangles)
        throw meshTooLarge("OFF", "triangles", options.maxTriangles);
      corners.insert(corners.end(), {polygon[0], polygon[k], polygon[k + 1]});
    }
  }
  // What follows the faces (an edge list in some writers) carries nothing a target needs.
  TriMesh mesh;
  mesh.V = Eigen::Map<const Vertices>(coords.data(), static_cast<Eigen::Index>(coords.size() / 3), 3);
  mesh.F = Eigen::Map<const Triangles>(corners.data(), static_cast<Eigen::Index>(corners.size() / 3), 3);
  return mesh;
}

}  // namespace billow
