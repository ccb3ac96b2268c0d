#include "io/mesh_file.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "io/off_reader.hpp"
#include "io/ply_reader.hpp"
#include "io/stl_reader.hpp"
#include "mesh/weld.hpp"
#include "util/error.hpp"

namespace billow {

std::string readFileBytes(const std::string& path, size_t maxBytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error("io.cannot-read", "Cannot open the file '" + path + "'. Check the name and that you may read it.");
  in.seekg(0, std::ios::end);
  const auto size = static_cast<size_t>(in.tellg());
  if (size > maxBytes)
    throw Error("io.too-large",
                "The file '" + path + "' is " + std::to_string(size >> 20) + " MB, larger than Billow accepts.");
  in.seekg(0);
  std::string bytes(size, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  return bytes;
}

TriMesh readMeshBytes(std::string_view bytes, const std::string& fileName, const MeshReadOptions& options) {
  std::string ext = fileName.substr(std::min(fileName.size(), fileName.rfind('.') + 1));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != "stl" && ext != "obj" && ext != "ply" && ext != "off")
    throw Error("io.unknown-format", "Billow cannot read '" + fileName +
                                         "': use a mesh in OBJ, STL, PLY or OFF format (.obj, .stl, .ply, .off).");
  // Said as such, not as a format's missing faces or header: a download or a copy that went wrong.
  if (bytes.empty()) throw Error("mesh.empty-file", "\"" + fileName + "\" is empty: the file holds no mesh.");
  if (ext == "stl") return readStl(bytes, options);  // welded as it is read: STL stores each triangle's corners
  TriMesh read;
  if (ext == "obj")
    read = readObj(bytes, options);
  else if (ext == "ply")
    read = readPly(bytes, options);
  else
    read = readOff(bytes, options);
  // Exporters may write a vertex per face or per normal: corners at one place are one vertex in every format, as in
  // STL, numbered in the order the faces first use them (the app's links hash that numbering, docs/formats.md).
  Vertices soup(3 * read.numTriangles(), 3);
  for (int t = 0; t < read.numTriangles(); ++t)
    for (int c = 0; c < 3; ++c) {
      const int v = read.F(t, c);
      // A bad index or a coordinate that is not a number: the mesh is refused, and validation counts them as read.
      if (v < 0 || v >= read.numVertices() || !read.V.row(v).allFinite()) return read;
      soup.row(3 * t + c) = read.V.row(v);
    }
  return weld(soup);
}

}  // namespace billow
