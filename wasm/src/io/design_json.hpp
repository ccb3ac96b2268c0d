// The design document (billow-design, version 1; docs/formats.md): the target, its real size, the seams as
// surface points or 3D points, internal connections, material and pressure. Read with every field
// validated; unknown fields are kept and written back.
//   { "format": "billow-design", "version": 1,
//     "target": { "example": "spot" } | { "obj": "cow.obj" } | { "file": "cow.obj" }
//               | { "vertices": [[x, y, z], ...], "triangles": [[i, j, k], ...] }, with "up": "+z" optional,
//               and "cutThinHandles": true, "closeHoles": true optional,
//     "size": { "height": 0.6 } | { "scale": 0.01 },
//     "seams": [ { "name": "belly", "closed": true, "weight": 1.0, "smooth": false,
//                  "points": [ { "face": 812, "bary": [0.2, 0.3, 0.5] }, [0.01, 0.12, -0.03] ] } ],
//     "connections": [ { "seams": [0, 3] } ] or [ [0, 3] ],
//     "material": { "name": "foil", "thickness": 2.5e-5, "youngs_modulus": 3.0e9 },
//     "pressure": 1000.0 }
// The height is meters along the target's up axis (its own y unless target.up names another); 3D seam points
// are in the target's own coordinates.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/up_axis.hpp"
#include "pattern/pattern.hpp"
#include "seams/seam_curve.hpp"

namespace billow {

struct DesignPoint {
  bool onSurface = false;  // true: `surface` ({face, bary}); false: `position`, projected when loaded
  SurfacePoint surface;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

struct DesignSeam {
  std::string name;
  std::vector<DesignPoint> points;
  bool closed = false;
  double weight = 1.0;  // sigma of Eq. 10
  bool smooth = false;
  // A side of a gusset band or the seam across its strip: the file's "band", which the app lays and keeps (its
  // record is kept as read when the design is written: designSeamJson's base).
  bool band = false;
};

struct DesignConnection {
  std::vector<int> seams;  // the seams an internal panel joins
};

struct DesignTarget {
  enum Kind { Example, Obj, File, Inline } kind = Example;
  // Example: the example id; Obj ("obj") and File ("file", the app's autosaved mesh): a mesh file path as
  // written, relative to the design file's folder (any format readMeshBytes knows, by extension).
  std::string name = "spot";
  TriMesh mesh;  // Inline
  UpAxis up;     // which of its own axes points up ("up"): where it stands, and what its height is measured along
  // Its thin handles cut through as it is loaded ("cutThinHandles", suggest/thin_handles.hpp): the designer chose to,
  // and the seams lie on the cut target's faces.
  bool cutThinHandles = false;
  // Its holes closed as it is loaded ("closeHoles", mesh/close_holes.hpp): an open mesh the designer chose to close.
  bool closeHoles = false;
};

struct Design {
  int version = 1;
  DesignTarget target;
  double height = 0.6;  // [m] along target.up; used when scale is 0
  double scale = 0;     // meters per target unit, when given instead of a height
  std::vector<DesignSeam> seams;
  std::vector<DesignConnection> connections;
  Material material;
  double pressure = 1000.0;                         // [Pa]
  nlohmann::json extra = nlohmann::json::object();  // the document as read: unknown fields survive a write
};

struct DesignWarning {
  std::string field;  // "seams[2].weight"
  std::string message;
};

struct DesignReadOptions {
  // true: a bad field is an error (billow::Error "design.bad-value" naming the field), as the CLI wants;
  // false: it falls back to its default with a warning (docs/formats.md, as the app reads autosaves).
  bool strict = true;
};

// Throws billow::Error: design.json (not JSON), design.unknown-format, design.version (newer than this
// reader), design.bad-value (strict), design.too-large.
Design readDesignJson(std::string_view text, const DesignReadOptions& options = {},
                      std::vector<DesignWarning>* warnings = nullptr);

// The parts of a design, read by the same rules as readDesignJson's: the app's worker
// (wasm/bindings/target_bindings.cpp) reads the seams, connections, material and pressure it is sent through
// these, so the CLI and the app accept and refuse the same designs. Messages name the document's field
// ("seams[2].weight") and the seam as the designer sees it ("seam 3 \"belly\""). A bad value throws
// design.bad-value (strict) or falls back with a warning.

// One seam: `index` is its place in the design's seams (-1: a seam on its own, as the app traces one). False
// when it is bad and not strict (it is then dropped).
bool readDesignSeam(const nlohmann::json& value, int index, DesignSeam& out, const DesignReadOptions& options = {},
                    std::vector<DesignWarning>* warnings = nullptr);
// The seams list; a bad seam is dropped when not strict. Throws design.too-large past 10,000 seams.
std::vector<DesignSeam> readDesignSeams(const nlohmann::json& list, const DesignReadOptions& options = {},
                                        std::vector<DesignWarning>* warnings = nullptr);
// Internal connections, [{ "seams": [i, j] }, ...] or [[i, j], ...], i and j indices of the design's seams
// (seamCount of them); a bad one is dropped when not strict. A seam joined to itself is read: the pattern
// builder reports it as a problem of that connection.
std::vector<DesignConnection> readDesignConnections(const nlohmann::json& list, size_t seamCount,
                                                    const DesignReadOptions& options = {},
                                                    std::vector<DesignWarning>* warnings = nullptr);
// The sheet: a preset's name stands for its figures, figures given beside it override them; over `base`.
Material readDesignMaterial(const nlohmann::json& value, const Material& base = {},
                            const DesignReadOptions& options = {}, std::vector<DesignWarning>* warnings = nullptr);
// The over-pressure [Pa], 1 Pa to 10 MPa; `fallback` when not strict and bad.
double readDesignPressure(const nlohmann::json& value, double fallback = 1000.0, const DesignReadOptions& options = {},
                          std::vector<DesignWarning>* warnings = nullptr);
// The target's up axis, a design's target.up when it has one: "+y", "-y", "+z", "-z", "+x" or "-x" (a design
// without one stands Y up).
UpAxis readDesignUp(const nlohmann::json& value, const DesignReadOptions& options = {},
                    std::vector<DesignWarning>* warnings = nullptr);
std::string writeDesignJson(const Design& design, int indent = 2);
// One seam as the design document writes it, over `base` (the fields it had when read, kept).
nlohmann::json designSeamJson(const DesignSeam& seam, const nlohmann::json& base = nlohmann::json());

// Folders searched for `{ "example": id }` targets (<dir>/<id>.obj): $BILLOW_EXAMPLES (':'-separated), then
// <exeDir>/../../web/public/examples when exeDir is given.
std::vector<std::string> exampleSearchPath(const std::string& exeDir = "");

// The design's target in its own coordinates. designPath: the design file (for relative "obj" paths).
// Throws billow::Error: design.example-not-found, io.cannot-read, the mesh readers' codes, design.bad-target.
TriMesh loadDesignTarget(const Design& design, const std::string& designPath,
                         const std::vector<std::string>& exampleDirs);

// Meters per target unit: size.scale, else size.height / (the target's extent along its up axis). The app's
// scale (web/src/app/up-axis.js heightScale) has the same rule.
double designScale(const Design& design, const TriMesh& targetOwnUnits);

// One seam's control points on `target` (any uniform scale of the target the points were written for: 3D
// points are multiplied by `scale` before projection); `index` as readDesignSeam's. Throws design.bad-value
// for a face the target does not have, and for a 3D point farther from the surface than the target's size
// (kMaxPointDistance x its bounding-box diagonal): such a point was written for another target or in other
// units, and projecting it would put the seam where the designer never drew it.
SeamSpec designSeamSpec(const DesignSeam& seam, int index, const TriMesh& target, const SurfaceProjector& projector,
                        double scale = 1.0);
constexpr double kMaxPointDistance = 1.0;

// A design's seams as SeamSpec on `target`, by designSeamSpec.
std::vector<SeamSpec> designSeamSpecs(const std::vector<DesignSeam>& seams, const TriMesh& target,
                                      const SurfaceProjector& projector, double scale = 1.0);

// The seam as the designer sees it: "seam 3" or "seam 3 \"belly\"" (index -1: "the seam", "the seam \"belly\"").
std::string seamLabel(int index, const std::string& name);

}  // namespace billow
