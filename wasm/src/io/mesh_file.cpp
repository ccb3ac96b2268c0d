#include "io/mesh_file.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "io/ply_reader.hpp"
#include "io/stl_reader.hpp"
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
  if (ext == "obj") return readObj(bytes, options);
  if (ext == "stl") return readStl(bytes, options);
  if (ext == "ply") return readPly(bytes, options);
  throw Error("io.unknown-format",
              "Billow cannot read '" + fileName + "': use a mesh in OBJ, STL or PLY format (.obj, .stl, .ply).");
}

}  // namespace billow
