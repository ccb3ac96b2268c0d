// Flat-sewn inflatables (issue 24): two pieces sewn around their outline (discs, pillows and tubes, letters, a
// star, a heart, a ring), a gusseted pillow and a cube of six squares are made as the example patterns say,
// settle from their own start in few Newton iterations, and two mirror pieces inflate into mirror halves.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "panel_checks.hpp"
#include "remesh/panel_mesher.hpp"
#include "simulate/coarse_start.hpp"
#include "simulate/example_patterns.hpp"
#include "test_support.hpp"

using namespace billow;
using billow::test::patternArea;
using billow::test::solve;

namespace {

Pattern flatCut(const std::string& name, int triangles, double aspect = 1) {
  ExampleOptions eo;
  eo.triangles = triangles;
  eo.size = 0.3;
  eo.aspect = aspect;
  return examplePattern(name, eo);
}

struct Settled {
  InflateResult result;
  StartReport start;
};

Settled settle(const Pattern& p) {
  const SewnMesh mesh = sewPattern(p);
  Settled s;
  s.result = solve(p, startPositions(p, mesh, {}, &s.start));
  return s;
}

}  // namespace

TEST(FlatCutExamples, AreTheSolidsTheySayWithEveryPieceSewn) {
  const double s = 0.3;
  // Rest areas: two discs, two squares, two squares and a strip a quarter as wide around them, two rings,
  // six squares (the curved outlines are polygons of about 2 % edges: within 1 %).
  const std::map<std::string, double> area = {{"mylar", 2 * M_PI * s * s},
                                              {"pillow", 2 * s * s},
                                              {"gusset-pillow", 2 * s * s + 4 * s * 0.25 * s},
                                              {"ring", 2 * M_PI * (s * s - 0.25 * s * s)},
                                              {"letter-L", 2 * (0.7 * s * s / 3 + s / 3 * 2 * s / 3)},
                                              {"cube", 6 * s * s}};
  for (const std::string& name : exampleNames()) {
    if (name.rfind("sphere3", 0) == 0) continue;
    for (const int triangles : {800, 4000}) {
      const Pattern p = flatCut(name, triangles);
      SCOPED_TRACE(name + " at " + std::to_string(triangles));
      SewnMesh mesh;
      ASSERT_NO_THROW(mesh = sewPattern(p));
      EXPECT_NEAR(mesh.numTriangles(), triangles, 0.25 * triangles);
      if (area.count(name)) {
        EXPECT_NEAR(patternArea(p), area.at(name), 0.01 * area.at(name));
      }
      // Closed: every outline vertex is sewn to another piece's (or, the gusset's two ends, its own).
      for (size_t k = 0; k < p.panels.size(); ++k)
        for (int v : outlineVertices(p.panels[k]))
          EXPECT_GE(mesh.stitchedCount[mesh.simVertex(int(k), v)], 2) << p.panels[k].name << " vertex " << v;
    }
  }
  // A cube's corners join three faces, its edges two.
  const SewnMesh cube = sewPattern(flatCut("cube", 1500));
  int corners = 0;
  for (int v = 0; v < cube.numVertices; ++v) corners += cube.stitchedCount[v] == 3;
  EXPECT_EQ(corners, 8);
}

TEST(FlatCutExamples, SharpTipsAreMeshedWithoutAnEdgeAcross) {
  // The mesher splits every inside edge between two outline points: at a star's tip one would be shared by the
  // front's and the back's tip triangles, four triangles on one sewn edge (the pattern would not sew).
  const double r = 0.15;
  Points2 star(10, 2);
  std::vector<int> corners;
  for (int k = 0; k < 10; ++k) {
    const double a = M_PI / 2 + M_PI * k / 5, rk = k % 2 ? 0.3 * r : r;
    star.row(k) << rk * std::cos(a), rk * std::sin(a);
    corners.push_back(k);
  }
  const ResampledBoundary boundary = resampleBoundary(star, corners, 0.01);
  const TriMesh m = meshPanel(boundary.points, 0.01);
  const int outline = int(boundary.points.rows());
  std::map<std::pair<int, int>, int> edges;
  for (int t = 0; t < m.F.rows(); ++t)
    for (int k = 0; k < 3; ++k) ++edges[std::minmax(m.F(t, k), m.F(t, (k + 1) % 3))];
  int chords = 0;
  for (const auto& [e, n] : edges) chords += n == 2 && e.first < outline && e.second < outline;
  EXPECT_EQ(chords, 0);
  EXPECT_GT(m.V.rows(), outline);  // the tips got inside points
}

TEST(FlatCutExamples, SettleFromTheirOwnStartInAtMostFortyNewtonIterations) {
  // The issue's bound, in the work of the pattern's own Newton iterations. From the sphere, 4:1 to 10:1 tubes and
  // L shapes of 1,300-1,600 triangles took 150-620 iterations, a 20:1 one did not settle in 1000.
  struct Case {
    std::string name;
    double aspect;
  };
  const std::vector<Case> cases = {{"mylar", 1},         {"pillow", 4},        {"pillow", 20},
                                   {"gusset-pillow", 1}, {"gusset-pillow", 4}, {"letter-L", 1},
                                   {"letter-C", 1},      {"heart", 1},         {"cube", 1}};
  for (const Case& c : cases)
    for (const int triangles : {1500, 4500}) {
      SCOPED_TRACE(c.name + " " + std::to_string(c.aspect) + ":1 at " + std::to_string(triangles));
      const Settled s = settle(flatCut(c.name, triangles, c.aspect));
      ASSERT_TRUE(s.result.converged);
      EXPECT_LE(s.result.iterations, 40);
      // The coarse levels (6 and 36 times smaller, solved first) cost less than 20 more: a thin curved strip
      // (the C) or a gusseted box from the sphere takes 70-110 iterations at 100-250 triangles.
      EXPECT_LE(s.start.coarseIterations / 6.0, 20);
    }
}

TEST(FlatCutExamples, RingsAndStarsSettleButSlowerThanTheIssueAsks) {
  // Not yet within the bound: the flat ring crawls away from its mirror-symmetric shape, a saddle of the
  // energy (the Hessian has a negative eigenvalue there: the shift stays at 0.1 p l while the ring warps like
  // a crisp, 1 % more volume). Its coarse levels (remeshed around the hole) stop at that saddle or warp
  // another way than the fine mesh prefers, and the fine level walks there along a nearly neutral direction,
  // 30-115 iterations instead of 130-250; the star's finest level takes 45-55 (bench/README.md).
  for (const std::string name : {"ring", "star"})
    for (const int triangles : {1500, 4500}) {
      SCOPED_TRACE(name + " at " + std::to_string(triangles));
      const Settled s = settle(flatCut(name, triangles));
      ASSERT_TRUE(s.result.converged);
      EXPECT_LE(s.result.iterations, name == "ring" ? 150 : 60);
    }
}

TEST(FlatCutExamples, TwoMirrorPiecesInflateIntoMirrorHalves) {
  // (Not the star: its five points settle bent to one side, 2 cm off the mirror image at 0.3 m.)
  for (const std::string name : {"mylar", "pillow", "letter-L", "letter-C", "heart"}) {
    SCOPED_TRACE(name);
    const Pattern p = flatCut(name, 1500);
    const SewnMesh mesh = sewPattern(p);
    const Settled s = settle(p);
    ASSERT_TRUE(s.result.converged);
    const Vertices& x = s.result.positions;
    // The seam's plane (least squares through the sewn outline).
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    int n = 0;
    for (int v = 0; v < mesh.numVertices; ++v)
      if (mesh.stitchedCount[v] >= 2) c += x.row(v).transpose(), ++n;
    c /= n;
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (int v = 0; v < mesh.numVertices; ++v)
      if (mesh.stitchedCount[v] >= 2) C += (x.row(v).transpose() - c) * (x.row(v) - c.transpose());
    const Eigen::Vector3d normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvectors().col(0);
    // The back is the front mirrored, vertex for vertex (example_patterns.cpp): so are their inflated shapes.
    double worst = 0, height = 0;
    for (int v = 0; v < p.panels[0].vertices.rows(); ++v) {
      const Eigen::Vector3d front = x.row(mesh.simVertex(0, v)), back = x.row(mesh.simVertex(1, v));
      const Eigen::Vector3d mirrored = front - 2 * (front - c).dot(normal) * normal;
      worst = std::max(worst, (mirrored - back).norm());
      height = std::max(height, std::abs((front - c).dot(normal)));
    }
    EXPECT_LT(worst, 1e-3 * 0.3);
    EXPECT_GT(height, 0.05 * 0.3);  // and inflated, not flat
  }
}
