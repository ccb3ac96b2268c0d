// Helpers shared by the native and wasm GoogleTest suites.
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#include "io/design_json.hpp"
#include "io/mesh_file.hpp"
#include "mesh/tri_mesh.hpp"
#include "mesh/validate.hpp"
#include "pattern/design_scene.hpp"
#include "simulate/example_patterns.hpp"
#include "simulate/inflate.hpp"

namespace billow::test {

inline constexpr double kPi = 3.14159265358979323846;

inline std::string meshPath(const std::string& name) { return std::string(BILLOW_MESH_DIR) + "/" + name; }

inline TriMesh loadShared(const std::string& name) { return readMeshBytes(readFileBytes(meshPath(name)), name); }

// The diagonal of a mesh's bounding box.
inline double boxDiagonal(const TriMesh& m) { return (m.V.colwise().maxCoeff() - m.V.colwise().minCoeff()).norm(); }

// A scene of a shared mesh, `height` meters tall, without seams yet.
inline std::unique_ptr<DesignScene> sharedScene(const std::string& name, double height = 0.6) {
  Design design;
  design.target.kind = DesignTarget::Obj;
  design.target.name = meshPath(name);
  design.height = height;
  return loadDesignTargetScene(design, "", {});
}

// A scene of a generated mesh, 0.6 m tall, without seams yet.
inline std::unique_ptr<DesignScene> sceneOf(const TriMesh& mesh) {
  Design design;
  design.target.kind = DesignTarget::Inline;
  design.height = 0.6;
  return makeTargetScene(design, mesh);
}

// A file of tests/data, and the app's example meshes (web/public/examples) that designs name.
// A repaired target (mesh/close_holes.hpp, suggest/thin_handles.hpp) as the validator sees it: usable, one closed
// surface of `genus`, its new triangles facing as the others (nothing turned). Its report, for what a test asks more.
inline ValidationReport expectClosedSurface(TriMesh mesh, int genus) {
  const ValidationReport report = validateTarget(mesh);
  EXPECT_TRUE(report.ok);
  EXPECT_FALSE(report.modified) << "the new triangles face out as the others do";
  EXPECT_EQ(report.stats.components, 1);
  EXPECT_EQ(report.stats.genus, genus);
  return report;
}

inline std::string dataPath(const std::string& name) { return std::string(BILLOW_TEST_DATA_DIR) + "/" + name; }
inline std::string examplesDir() { return std::string(BILLOW_TEST_DATA_DIR) + "/../../web/public/examples"; }

// Each triangle split in four at its edges' midpoints: the same surface, four times the triangles (a scan's density).
inline TriMesh splitInFour(const TriMesh& m) {
  std::map<std::uint64_t, int> midpoint;
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < m.numVertices(); ++i) v.push_back(m.V.row(i).transpose());
  auto middle = [&](int a, int b) {
    const auto [it, added] = midpoint.try_emplace(edgeKey(a, b), int(v.size()));
    if (added) v.push_back(0.5 * (v[size_t(a)] + v[size_t(b)]));
    return it->second;
  };
  TriMesh out;
  out.F.resize(4 * m.numTriangles(), 3);
  for (int f = 0; f < m.numTriangles(); ++f) {
    const int a = m.F(f, 0), b = m.F(f, 1), c = m.F(f, 2);
    const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
    out.F.row(4 * f) = Eigen::Vector3i(a, ab, ca);
    out.F.row(4 * f + 1) = Eigen::Vector3i(ab, b, bc);
    out.F.row(4 * f + 2) = Eigen::Vector3i(ca, bc, c);
    out.F.row(4 * f + 3) = Eigen::Vector3i(ab, bc, ca);
  }
  out.V.resize(int(v.size()), 3);
  for (size_t i = 0; i < v.size(); ++i) out.V.row(int(i)) = v[i].transpose();
  return out;
}

// The longest optimizer runs (9-17 s each in wasm, most of the wasm suite's time) are tested natively only: the
// wasm build runs the same optimizer in the node and end-to-end suites.
#ifdef __EMSCRIPTEN__
#define BILLOW_NATIVE_ONLY_LONG_RUN() GTEST_SKIP() << "a long optimizer run, tested natively"
#else
#define BILLOW_NATIVE_ONLY_LONG_RUN() (void)0
#endif

// The billow CLI built next to this test binary (native suites only run it).
inline std::string cliPath() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  const std::string exe(buf, n > 0 ? static_cast<size_t>(n) : 0);
  return exe.substr(0, exe.find_last_of('/')) + "/billow";
}

// Runs a shell command with its stderr dropped; its exit code, or -1 when it did not exit normally.
inline int runQuiet(const std::string& command) {
  const int status = std::system((command + " 2>/dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Runs a shell command and returns its exit code (-1 when it did not exit normally); its stdout and stderr
// go to `output`.
inline int runCapture(const std::string& command, std::string& output) {
  output.clear();
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return -1;
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) output.append(buf, n);
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// An example pattern (example_patterns.hpp) of about this many triangles, with its other defaults.
inline Pattern example(const std::string& name, int triangles) {
  ExampleOptions eo;
  eo.triangles = triangles;
  return examplePattern(name, eo);
}

// Inflates `p` from x0 until it converges or fails.
inline InflateResult solve(const Pattern& p, const Vertices& x0, const InflateOptions& o = {}) {
  InflationSolver s(sewPattern(p), p.material, p.pressure, o, x0);
  while (s.step(50) == InflateState::Running) {
  }
  return s.result();
}

}  // namespace billow::test
