// Target validation: is this mesh a closed shape Billow can design on? One implementation for the
// worker (through the bindings) and the CLI (`billow check`), so both give the same report.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "mesh/up_axis.hpp"

namespace billow {

struct ValidationOptions {
  int maxTriangles = 500000;           // beyond the interactive budget of the solver: refused with a message
  double degenerateAreaRatio = 1e-14;  // a triangle is degenerate when its area < ratio * (bbox diagonal)^2
  bool guessUp = true;                 // fill MeshStats::standing (a mesh opened anew, not a design's target)
};

struct MeshIssue {
  std::string code;      // stable id, e.g. "mesh.open"
  std::string severity;  // "error" (cannot be used), "warning" (usable, worth knowing), "notice" (fixed for you)
  std::string message;   // the designer's words
  int count = 0;         // how many elements are concerned
  bool hasLocation = false;
  Eigen::Vector3d location = Eigen::Vector3d::Zero();  // a representative point, in the mesh's own units
};

struct MeshStats {
  int vertices = 0;  // referenced vertices
  int triangles = 0;
  int edges = 0;
  int components = 0;
  int boundaryEdges = 0;
  int holes = 0;   // boundary loops
  int genus = -1;  // -1 when undefined (open, non-manifold or several components)
  Eigen::Vector3d bboxMin = Eigen::Vector3d::Zero(), bboxMax = Eigen::Vector3d::Zero();
  double area = 0;    // in the mesh's own units squared
  double volume = 0;  // signed, after any orientation fix; > 0 for outward normals
  UpGuess standing;   // the axis it stands on (mesh/up_axis.hpp), with ValidationOptions::guessUp
};

struct ValidationReport {
  bool ok = false;        // no issue of severity "error"
  bool modified = false;  // the mesh's triangles were reoriented or their copies left out (mesh.F changed)
  MeshStats stats;
  std::vector<MeshIssue> issues;  // errors first
};

// Checks mesh and repairs in place what has one right answer, each with a notice: an inside-out mesh flipped, stray
// triangles turned, the copies of a triangle that appears twice left out (mesh.F then has fewer rows).
ValidationReport validateTarget(TriMesh& mesh, const ValidationOptions& options = {});

// The report as JSON text (the same text natively and in wasm).
std::string toJson(const ValidationReport& report);

}  // namespace billow
