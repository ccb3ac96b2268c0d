#include "io/ply_reader.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "util/error.hpp"

namespace billow {

namespace {

enum class Format { Ascii, LittleEndian, BigEndian };
enum class Scalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct Property {
  std::string name;
  Scalar type = Scalar::Float32;  // the item type for a list
  bool isList = false;
  Scalar countType = Scalar::UInt8;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  size_t bodyOffset = 0;
  long long lines = 0;  // header lines, for ascii body line numbers
};

int sizeOf(Scalar t) {
  static const int sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[static_cast<int>(t)];
}

bool isInteger(Scalar t) { return t != Scalar::Float32 && t != Scalar::Float64; }

bool parseScalar(std::string_view w, Scalar& t) {
  static const struct {
    const char* name;
    Scalar type;
  } names[] = {{"char", Scalar::Int8},      {"int8", Scalar::Int8},       {"uchar", Scalar::UInt8},
               {"uint8", Scalar::UInt8},    {"short", Scalar::Int16},     {"int16", Scalar::Int16},
               {"ushort", Scalar::UInt16},  {"uint16", Scalar::UInt16},   {"int", Scalar::Int32},
               {"int32", Scalar::Int32},    {"uint", Scalar::UInt32},     {"uint32", Scalar::UInt32},
               {"float", Scalar::Float32},  {"float32", Scalar::Float32}, {"double", Scalar::Float64},
               {"float64", Scalar::Float64}};
  for (const auto& n : names)
    if (w == n.name) return t = n.type, true;
  return false;
}

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  size_t pos = 0;
  while (true) {
    pos = line.find_first_not_of(" \t\r", pos);
    if (pos == std::string_view::npos) return words;
    const size_t end = std::min(line.find_first_of(" \t\r", pos), line.size());
    words.push_back(line.substr(pos, end - pos));
    pos = end;
  }
}

[[noreturn]] void failHeader(long long line, const std::string& what) {
  throw Error("ply.bad-header",
              "The PLY file's header is malformed at line " + std::to_string(line) + ": " + what + ".");
}

void parseFormat(const std::vector<std::string_view>& w, Header& header, long long line) {
  if (w.size() != 3) failHeader(line, "the format line needs a format and a version, e.g. 'format ascii 1.0'");
  if (w[1] == "ascii")
    header.format = Format::Ascii;
  else if (w[1] == "binary_little_endian")
    header.format = Format::LittleEndian;
  else if (w[1] == "binary_big_endian")
    header.format = Format::BigEndian;
  else
    throw Error("ply.unsupported-format", "The PLY file is in the format '" + std::string(w[1]) +
                                              "', which Billow cannot read (it reads ascii, binary_little_endian "
                                              "and binary_big_endian).");
}

void parseElement(const std::vector<std::string_view>& w, Header& header, long long line) {
  if (w.size() != 3) failHeader(line, "an element needs a name and a count, e.g. 'element vertex 8'");
  const std::string count(w[2]);
  char* end = nullptr;
  const long long n = std::strtoll(count.c_str(), &end, 10);
  if (end != count.c_str() + count.size() || n < 0 || n == std::numeric_limits<long long>::max())
    failHeader(line, "'" + count + "' is not a count of elements");
  header.elements.push_back({std::string(w[1]), n, {}});
}

void parseProperty(const std::vector<std::string_view>& w, Header& header, long long line) {
  if (header.elements.empty()) failHeader(line, "a property comes before any element");
  Property p;
  const bool list = w.size() >= 2 && w[1] == "list";
  if (w.size() != (list ? 5u : 3u))
    failHeader(line, list ? "a list property needs a count type, an item type and a name"
                          : "a property needs a type and a name, e.g. 'property float x'");
  const std::string_view type = w[list ? 3 : 1];
  if (!parseScalar(type, p.type)) failHeader(line, "'" + std::string(type) + "' is not a PLY type");
  if (list && (!parseScalar(w[2], p.countType) || !isInteger(p.countType)))
    failHeader(line, "'" + std::string(w[2]) + "' cannot count the items of a list");
  p.isList = list;
  p.name = std::string(w.back());
  header.elements.back().properties.push_back(p);
}

Header parseHeader(std::string_view bytes) {
  Header header;
  bool haveFormat = false;
  size_t pos = 0;
  while (pos < bytes.size()) {
    size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos) end = bytes.size();
    const std::vector<std::string_view> w = splitWords(bytes.substr(pos, end - pos));
    const long long line = ++header.lines;
    pos = std::min(end + 1, bytes.size());
    if (line == 1) {
      if (w.size() != 1 || w[0] != "ply")
        throw Error("ply.not-ply", "The file does not begin with 'ply', so it is not a PLY file.");
    } else if (w.empty() || w[0] == "comment" || w[0] == "obj_info") {
      continue;
    } else if (w[0] == "format") {
      parseFormat(w, header, line), haveFormat = true;
    } else if (w[0] == "element") {
      parseElement(w, header, line);
    } else if (w[0] == "property") {
      parseProperty(w, header, line);
    } else if (w[0] == "end_header") {
      if (!haveFormat) failHeader(line, "the header ends without a 'format' line");
      header.bodyOffset = pos;
      return header;
    } else {
      failHeader(line, "'" + std::string(w[0]) + "' is not a PLY header keyword");
    }
  }
  throw Error("ply.no-header-end",
              "The PLY file's header never ends (there is no 'end_header' line). The file "
              "is cut off or is not a PLY file.");
}

// Reads the body value by value in any of the three formats; knows which element it is in for messages.
class Body {
 public:
  Body(std::string_view bytes, const Header& h)
      : s_(bytes), pos_(h.bodyOffset), format_(h.format), line_(h.lines + 1) {}

  void at(const std::string& element, long long index) { element_ = &element, index_ = index; }
  size_t remaining() const { return s_.size() - pos_; }

  double value(Scalar t) { return format_ == Format::Ascii ? asciiValue() : binaryValue(t); }

  void skip(Scalar t) {
    if (format_ == Format::Ascii) return void(word());
    need(static_cast<size_t>(sizeOf(t)));
    pos_ += static_cast<size_t>(sizeOf(t));
  }

  // A list's length or a vertex index: an integer in [0, limit].
  long long integer(Scalar t, long long limit, const char* what) {
    const double v = value(t);
    if (!(v >= 0 && v <= static_cast<double>(limit)) || v != std::floor(v))
      fail("ply.bad-value", std::string(what) + " is " + formatNumber(v) + ", which cannot be right");
    return static_cast<long long>(v);
  }

  [[noreturn]] void fail(const std::string& code, const std::string& what) const {
    const std::string where =
        format_ == Format::Ascii ? "line " + std::to_string(line_) : "byte " + std::to_string(pos_);
    throw Error(code, "The PLY file is malformed in " + *element_ + " " + std::to_string(index_) + " (" + where +
                          "): " + what + ".");
  }

  static std::string formatNumber(double v) {
    std::string s = std::to_string(v);
    if (s.find('.') != std::string::npos) s.erase(s.find_last_not_of("0.") + 1);  // 7.000000 -> 7
    return s.empty() ? "0" : s;
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

  void need(size_t n) {
    if (remaining() < n) fail("ply.truncated", "the file ends here; it was probably cut off");
  }

  std::string_view word() {
    for (; pos_ < s_.size() && isSpace(s_[pos_]); ++pos_)
      if (s_[pos_] == '\n') ++line_;
    const size_t start = pos_;
    while (pos_ < s_.size() && !isSpace(s_[pos_])) ++pos_;
    if (start == pos_) fail("ply.truncated", "the file ends here; it was probably cut off");
    return s_.substr(start, pos_ - start);
  }

  double asciiValue() {
    const std::string w(word());
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);  // "nan" and "inf" are read, for validation to report
    if (end != w.c_str() + w.size()) fail("ply.syntax", "'" + w + "' is not a number");
    return v;
  }

  double binaryValue(Scalar t) {
    const size_t n = static_cast<size_t>(sizeOf(t));
    need(n);
    std::uint64_t bits = 0;
    for (size_t i = 0; i < n; ++i) {
      const auto byte = static_cast<unsigned char>(s_[pos_ + i]);
      const size_t shift = 8 * (format_ == Format::LittleEndian ? i : n - 1 - i);
      bits |= std::uint64_t{byte} << shift;
    }
    pos_ += n;
    return decode(t, bits);
  }

  static double decode(Scalar t, std::uint64_t bits) {
    switch (t) {
      case Scalar::Int8:
        return static_cast<std::int8_t>(bits);
      case Scalar::UInt8:
        return static_cast<std::uint8_t>(bits);
      case Scalar::Int16:
        return static_cast<std::int16_t>(bits);
      case Scalar::UInt16:
        return static_cast<std::uint16_t>(bits);
      case Scalar::Int32:
        return static_cast<std::int32_t>(bits);
      case Scalar::UInt32:
        return static_cast<std::uint32_t>(bits);
      case Scalar::Float32: {
        const auto b32 = static_cast<std::uint32_t>(bits);
        float f;
        std::memcpy(&f, &b32, sizeof f);
        return f;
      }
      case Scalar::Float64: {
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
    }
    return 0;
  }

  std::string_view s_;
  size_t pos_;
  Format format_;
  long long line_;
  const std::string* element_ = nullptr;
  long long index_ = 0;
};

// The fewest bytes one item of e can take: binary sizes (lists may be empty), or in ascii one character
// and one separator per value.
size_t minimumBytes(const Element& e, Format format) {
  size_t bytes = 0;
  for (const Property& p : e.properties)
    bytes += format == Format::Ascii ? 2 : static_cast<size_t>(sizeOf(p.isList ? p.countType : p.type));
  return bytes;
}

// Counts that the file cannot hold are refused before anything is allocated for them.
void checkCounts(const Header& h, size_t bodyBytes) {
  size_t left = bodyBytes + 1;  // the last ascii value needs no separator
  for (const Element& e : h.elements) {
    const size_t each = minimumBytes(e, h.format);
    if (each == 0) continue;
    if (static_cast<unsigned long long>(e.count) > left / each)
      throw Error("ply.bad-count", "The PLY header announces " + std::to_string(e.count) + " elements '" + e.name +
                                       "', but the file is far too small to hold them (" + std::to_string(bodyBytes) +
                                       " bytes after the header). It is damaged or cut off.");
    left -= static_cast<size_t>(e.count) * each;
  }
}

struct Target {
  const Element* vertex = nullptr;
  const Element* face = nullptr;  // 'face', or where the file has none, 'tristrips' (strips is then true)
  bool strips = false;
  int xyz[3] = {-1, -1, -1};  // property positions of x, y, z in the vertex element
  int indices = -1;           // property position of the face's (or strips') index list
};

Target findTarget(const Header& h) {
  Target t;
  const Element* strips = nullptr;
  for (const Element& e : h.elements) {
    if (e.name == "vertex" && !t.vertex) t.vertex = &e;
    if (e.name == "face" && !t.face) t.face = &e;
    if (e.name == "tristrips" && !strips) strips = &e;
  }
  // Scanned meshes of the 1990s (the Stanford and Cyberware ones) come as triangle strips instead of faces.
  if ((!t.face || t.face->count == 0) && strips && strips->count > 0) t.face = strips, t.strips = true;
  if (!t.vertex) throw Error("ply.missing-coordinates", "The PLY file has no 'vertex' element, so no points to use.");
  for (int k = 0; k < 3; ++k) {
    const char* axis[] = {"x", "y", "z"};
    for (size_t i = 0; i < t.vertex->properties.size(); ++i)
      if (t.vertex->properties[i].name == axis[k] && !t.vertex->properties[i].isList) t.xyz[k] = static_cast<int>(i);
    if (t.xyz[k] < 0)
      throw Error("ply.missing-coordinates", std::string("The PLY file's vertices have no '") + axis[k] +
                                                 "' coordinate, so they cannot be placed.");
  }
  if (!t.face || t.face->count == 0)
    throw Error("ply.no-faces",
                "The PLY file contains no faces (it may be a point cloud), so there is no surface to use.");
  for (size_t i = 0; i < t.face->properties.size(); ++i) {
    const Property& p = t.face->properties[i];
    if (p.isList && (p.name == "vertex_indices" || p.name == "vertex_index")) t.indices = static_cast<int>(i);
  }
  if (t.indices < 0)
    throw Error("ply.missing-indices", std::string("The PLY file's ") + (t.strips ? "triangle strips" : "faces") +
                                           " have no 'vertex_indices' list, so they join no vertices.");
  return t;
}

void checkLimits(const Target& t, const MeshReadOptions& options) {
  const long long maxVertices = std::min<long long>(options.maxVertices, std::numeric_limits<int>::max());
  if (t.vertex->count > maxVertices) throw meshTooLarge("PLY", "vertices", maxVertices, t.vertex->count);
  if (!t.strips && t.face->count > options.maxTriangles) throw meshTooLarge("PLY", "triangles", options.maxTriangles);
}

void skipProperty(Body& body, const Property& p) {
  if (!p.isList) return body.skip(p.type);
  const long long n = body.integer(p.countType, std::numeric_limits<long long>::max() / 2, "a list's length");
  for (long long i = 0; i < n; ++i) body.skip(p.type);
}

void readVertex(Body& body, const Target& t, double* xyz) {
  const auto& props = t.vertex->properties;
  for (size_t i = 0; i < props.size(); ++i) {
    int axis = -1;
    for (int k = 0; k < 3; ++k)
      if (t.xyz[k] == static_cast<int>(i)) axis = k;
    if (axis >= 0)
      xyz[axis] = body.value(props[i].type);
    else
      skipProperty(body, props[i]);
  }
}

std::string vertexRange(long long count) {
  return count == 0 ? "the file has no vertices" : "the vertices are numbered 0 to " + std::to_string(count - 1);
}

void readFace(Body& body, const Target& t, long long face, std::vector<int>& corners, const MeshReadOptions& options) {
  const auto& props = t.face->properties;
  for (size_t i = 0; i < props.size(); ++i) {
    if (static_cast<int>(i) != t.indices) {
      skipProperty(body, props[i]);
      continue;
    }
    const long long n = body.integer(props[i].countType, std::numeric_limits<int>::max(), "the number of corners");
    if (n < 3) body.fail("ply.bad-face", "a face needs at least three corners, this one has " + std::to_string(n));
    int first = -1, previous = -1;
    for (long long k = 0; k < n; ++k) {
      const double v = body.value(props[i].type);
      if (!(v >= 0 && v < static_cast<double>(t.vertex->count)) || v != std::floor(v))
        throw Error("ply.bad-index", "Face " + std::to_string(face) + " of the PLY file refers to vertex " +
                                         Body::formatNumber(v) + ", which does not exist (" +
                                         vertexRange(t.vertex->count) + ").");
      const int index = static_cast<int>(v);
      if (k >= 2) {
        if (static_cast<long long>(corners.size() / 3) >= options.maxTriangles)
          throw meshTooLarge("PLY", "triangles", options.maxTriangles);
        corners.insert(corners.end(), {first, previous, index});
      }
      if (k == 0) first = index;
      previous = index;
    }
  }
}

// A strip's list: each vertex after the first two makes a triangle with the two before it, every second one turned
// so that all face the same way; -1 ends a strip. Triangles with a repeated corner (how strips are joined) are left
// out.
void readStrips(Body& body, const Target& t, std::vector<int>& corners, const MeshReadOptions& options) {
  const auto& props = t.face->properties;
  for (size_t i = 0; i < props.size(); ++i) {
    if (static_cast<int>(i) != t.indices) {
      skipProperty(body, props[i]);
      continue;
    }
    const long long n = body.integer(props[i].countType, std::numeric_limits<long long>::max() / 2,
                                     "the number of vertices in the strips");
    int a = -1, b = -1;
    long long inStrip = 0;
    for (long long k = 0; k < n; ++k) {
      const double v = body.value(props[i].type);
      if (v == -1) {
        inStrip = 0;
        continue;
      }
      if (!(v >= 0 && v < static_cast<double>(t.vertex->count)) || v != std::floor(v))
        throw Error("ply.bad-index", "The triangle strips of the PLY file refer to vertex " + Body::formatNumber(v) +
                                         ", which does not exist (" + vertexRange(t.vertex->count) + ").");
      const int c = static_cast<int>(v);
      if (inStrip >= 2 && a != b && b != c && a != c) {
        if (static_cast<long long>(corners.size() / 3) >= options.maxTriangles)
          throw meshTooLarge("PLY", "triangles", options.maxTriangles);
        if (inStrip % 2 == 0)
          corners.insert(corners.end(), {a, b, c});
        else
          corners.insert(corners.end(), {b, a, c});
      }
      a = b, b = c, ++inStrip;
    }
  }
}

}  // namespace

TriMesh readPly(std::string_view bytes, const MeshReadOptions& options) {
  const Header header = parseHeader(bytes);
  const Target target = findTarget(header);
  checkCounts(header, bytes.size() - header.bodyOffset);
  checkLimits(target, options);
  TriMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(target.vertex->count), 3);
  std::vector<int> corners;
  corners.reserve(static_cast<size_t>(3 * target.face->count));
  Body body(bytes, header);
  for (const Element& e : header.elements) {
    if (e.properties.empty()) continue;  // nothing to read, however large its count (checkCounts cannot bound it)
    for (long long i = 0; i < e.count; ++i) {
      body.at(e.name, i);
      if (&e == target.vertex)
        readVertex(body, target, &mesh.V(i, 0));
      else if (&e == target.face && target.strips)
        readStrips(body, target, corners, options);
      else if (&e == target.face)
        readFace(body, target, i, corners, options);
      else
        for (const Property& p : e.properties) skipProperty(body, p);
    }
  }
  mesh.F = Eigen::Map<const Triangles>(corners.data(), static_cast<Eigen::Index>(corners.size() / 3), 3);
  return mesh;
}

}  // namespace billow
