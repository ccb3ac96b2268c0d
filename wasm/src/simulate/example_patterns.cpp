#include "simulate/example_patterns.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <map>

#include "remesh/panel_mesher.hpp"
#include "util/error.hpp"

namespace billow {
namespace {

// Triangulates the strip between two rows of points A and B ("zipper"): each step advances the row whose
// next point comes first in the parameter s (angle or normalized position). Cyclic rows wrap by `period`.
void zip(const std::vector<int>& A, const std::vector<double>& sA, const std::vector<int>& B,
         const std::vector<double>& sB, bool cyclic, double period, std::vector<Eigen::Vector3i>& out) {
  const int na = int(A.size()), nb = int(B.size());
  int j0 = 0;
  if (cyclic) {
    for (int j = 1; j < nb; ++j)
      if (std::abs(std::remainder(sB[j] - sA[0], period)) < std::abs(std::remainder(sB[j0] - sA[0], period))) j0 = j;
  }
  const int endA = cyclic ? na : na - 1, endB = cyclic ? nb : nb - 1;
  auto pa = [&](int i) { return sA[i % na] + (cyclic ? period * (i / na) : 0); };
  const double shiftB = cyclic ? sA[0] + std::remainder(sB[j0] - sA[0], period) - sB[j0] : 0;
  auto pb = [&](int j) { return sB[(j0 + j) % nb] + shiftB + (cyclic ? period * ((j0 + j) / nb) : 0); };
  int i = 0, j = 0;
  while (i < endA || j < endB) {
    const bool advanceA = j >= endB || (i < endA && pa(i + 1) < pb(j + 1));
    const int a = A[i % na], b = B[(j0 + j) % nb];
    if (advanceA) {
      out.push_back({a, A[(i + 1) % na], b});
      ++i;
    } else {
      out.push_back({a, B[(j0 + j + 1) % nb], b});
      ++j;
    }
  }
}

// Makes every triangle counterclockwise in the panel plane.
Triangles orient(const PanelVertices& V, const std::vector<Eigen::Vector3i>& tris) {
  Triangles F(tris.size(), 3);
  for (size_t t = 0; t < tris.size(); ++t) {
    Eigen::Vector3i f = tris[t];
    const Eigen::Vector2d e1 = V.row(f[1]) - V.row(f[0]), e2 = V.row(f[2]) - V.row(f[0]);
    if (e1.x() * e2.y() - e1.y() * e2.x() < 0) std::swap(f[1], f[2]);
    F.row(t) = f.transpose();
  }
  return F;
}

// The other side of a two-sided balloon: seen from outside, a panel is mirrored; vertex numbers are kept, so
// boundary vertex i of the front is sewn to boundary vertex i of the back.
Panel mirrored(const Panel& p, const std::string& name) {
  Panel q = p;
  q.name = name;
  q.vertices.col(1) *= -1;
  q.triangles.col(1).swap(q.triangles.col(2));
  return q;
}

Pattern twoSided(const Panel& front, const ExampleOptions& o) {
  Pattern p;
  p.panels = {front, mirrored(front, "back")};
  for (int v : outlineVertices(front)) p.stitches.push_back({0, v, 1, v});
  p.material = o.material;
  p.pressure = o.pressure;
  return p;
}

Points2 toPoints(const std::vector<Eigen::Vector2d>& pts) {
  Points2 P(pts.size(), 2);
  for (size_t i = 0; i < pts.size(); ++i) P.row(i) = pts[i].transpose();
  return P;
}

// Appends a circle of n points of radius r (turned by half a step when `shifted`, so that rows zip into
// well-shaped triangles), its points' indices and angles.
void appendCircle(double r, int n, bool shifted, std::vector<Eigen::Vector2d>& pts,
                  std::vector<std::vector<int>>& rings, std::vector<std::vector<double>>& angles) {
  std::vector<int> ring;
  std::vector<double> ang;
  for (int j = 0; j < n; ++j) {
    const double th = 2 * M_PI * (j + 0.5 * shifted) / n;
    ring.push_back(int(pts.size()));
    ang.push_back(th);
    pts.push_back(r * Eigen::Vector2d(std::cos(th), std::sin(th)));
  }
  rings.push_back(ring);
  angles.push_back(ang);
}

// Disc of radius a: K concentric rings with 6k points each (vertex 0 = centre), about 6 K^2 triangles.
Panel disc(double a, int K) {
  std::vector<Eigen::Vector2d> pts = {{0, 0}};
  std::vector<std::vector<int>> rings = {{0}};
  std::vector<std::vector<double>> angles = {{0}};
  for (int k = 1; k <= K; ++k) appendCircle(a * double(k) / K, 6 * k, k % 2, pts, rings, angles);
  std::vector<Eigen::Vector3i> tris;
  for (int j = 0; j < 6; ++j) tris.push_back({0, rings[1][j], rings[1][(j + 1) % 6]});
  for (int k = 2; k <= K; ++k) zip(rings[k - 1], angles[k - 1], rings[k], angles[k], true, 2 * M_PI, tris);
  Panel p;
  p.name = "front";
  p.vertices = toPoints(pts);
  p.triangles = orient(p.vertices, tris);
  return p;
}

// A rectangle `width` by `length` of nx by ny cells, each split in two.
Panel rectangle(double width, double length, int nx, int ny) {
  Panel p;
  p.name = "front";
  p.vertices.resize((nx + 1) * (ny + 1), 2);
  for (int i = 0; i <= ny; ++i)
    for (int j = 0; j <= nx; ++j)
      p.vertices.row(i * (nx + 1) + j) << width * j / nx - width / 2, length * i / ny - length / 2;
  std::vector<Eigen::Vector3i> tris;
  for (int i = 0; i < ny; ++i)
    for (int j = 0; j < nx; ++j) {
      const int a = i * (nx + 1) + j, b = a + 1, c = a + nx + 1, d = c + 1;
      // Diagonals alternate (a "union jack" pattern) so the quilt has no preferred shear direction.
      if ((i + j) % 2 == 0) {
        tris.push_back({a, b, d});
        tris.push_back({a, d, c});
      } else {
        tris.push_back({a, b, c});
        tris.push_back({b, d, c});
      }
    }
  p.triangles = orient(p.vertices, tris);
  return p;
}

// Gore of a sphere of radius R spanning 120 degrees: x = meridian arc length in [0, pi R], half-width
// w(x) = (pi/3) R sin(x/R). Columns of points across; the tips are single points. Bottom boundary point
// of each column first, top boundary point last.
Panel gore(double R, int columns, std::vector<std::pair<int, int>>& sides) {
  const double h = M_PI * R / columns;
  std::vector<Eigen::Vector2d> pts;
  std::vector<std::vector<int>> cols;
  std::vector<std::vector<double>> params;
  for (int k = 0; k <= columns; ++k) {
    const double x = h * k, w = M_PI / 3 * R * std::sin(x / R);
    const int n = (k == 0 || k == columns) ? 1 : std::max(2, int(std::lround(2 * w / h)) + 1);
    std::vector<int> col;
    std::vector<double> par;
    for (int i = 0; i < n; ++i) {
      const double s = n == 1 ? 0.5 : double(i) / (n - 1);
      col.push_back(int(pts.size()));
      par.push_back(s);
      pts.push_back({x - M_PI * R / 2, -w + 2 * w * s});
    }
    sides.push_back({col.front(), col.back()});
    cols.push_back(col);
    params.push_back(par);
  }
  std::vector<Eigen::Vector3i> tris;
  for (int k = 0; k < columns; ++k) zip(cols[k], params[k], cols[k + 1], params[k + 1], false, 0, tris);
  Panel p;
  p.vertices = toPoints(pts);
  p.triangles = orient(p.vertices, tris);
  return p;
}

// A panel meshed inside a closed counterclockwise polygon, edges about h, the given polygon vertices kept as
// corners.
Panel outlinePanel(const Points2& polygon, const std::vector<int>& corners, double h) {
  const ResampledBoundary boundary = resampleBoundary(polygon, corners, h);
  const TriMesh m = meshPanel(boundary.points, h);
  Panel p;
  p.name = "front";
  p.vertices = m.V.leftCols(2);
  p.triangles = m.F;
  return p;
}

// Two mirror pieces cut to a polygon outline, about `triangles` in all.
Pattern outlinePair(const Points2& polygon, const std::vector<int>& corners, const ExampleOptions& o) {
  // Two panels of equilateral triangles of edge h (area sqrt(3)/4 h^2 each).
  // (The mesher refines to edges within 1.25 h and 28 degrees: about 1.37 times that count, hence 1.17 h.)
  const double h = 1.17 * std::sqrt(2 * 4 * signedArea(polygon) / (std::sqrt(3.0) * o.triangles));
  return twoSided(outlinePanel(polygon, corners, h), o);
}

// Arc of radius r about the origin from angle a0 to a1, `n` pieces (n + 1 points, both ends).
void appendArc(std::vector<Eigen::Vector2d>& pts, double r, double a0, double a1, int n) {
  for (int k = 0; k <= n; ++k) {
    const double a = a0 + (a1 - a0) * k / n;
    pts.push_back(r * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
}

// Flat ring of outer radius a and inner radius b: concentric rows zipped together, each about h apart.
Panel annulus(double a, double b, double h) {
  const int rows = std::max(2, int(std::lround((a - b) / h)) + 1);
  std::vector<Eigen::Vector2d> pts;
  std::vector<std::vector<int>> rings;
  std::vector<std::vector<double>> angles;
  for (int k = 0; k < rows; ++k) {
    const double r = b + (a - b) * k / (rows - 1);
    appendCircle(r, std::max(6, int(std::lround(2 * M_PI * r / h))), k % 2, pts, rings, angles);
  }
  std::vector<Eigen::Vector3i> tris;
  for (int k = 1; k < rows; ++k) zip(rings[k - 1], angles[k - 1], rings[k], angles[k], true, 2 * M_PI, tris);
  Panel p;
  p.name = "front";
  p.vertices = toPoints(pts);
  p.triangles = orient(p.vertices, tris);
  return p;
}

// Panels made in place on a closed solid (a cube, a gusseted pillow): `place` puts a flat panel point on the
// solid, the panel's counterclockwise side facing out. Boundary vertices that land on the same point are sewn.
struct PlacedPanel {
  Panel panel;
  std::function<Eigen::Vector3d(const Eigen::Vector2d&)> place;
};

// Laid flat in the plane through `origin` spanned by u and v (u x v pointing out).
std::function<Eigen::Vector3d(const Eigen::Vector2d&)> inPlane(const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                                                               const Eigen::Vector3d& v) {
  return [=](const Eigen::Vector2d& q) { return Eigen::Vector3d(origin + q.x() * u + q.y() * v); };
}

Pattern sewnWherePanelsMeet(const std::vector<PlacedPanel>& placed, double size, const ExampleOptions& o) {
  Pattern p;
  std::map<std::array<long long, 3>, std::vector<std::pair<int, int>>> at;  // quantized point -> (panel, vertex)
  const double quantum = 1e-6 * size;
  for (size_t i = 0; i < placed.size(); ++i) {
    p.panels.push_back(placed[i].panel);
    for (int v : outlineVertices(placed[i].panel)) {
      const Eigen::Vector3d x = placed[i].place(placed[i].panel.vertices.row(v).transpose());
      at[{std::llround(x.x() / quantum), std::llround(x.y() / quantum), std::llround(x.z() / quantum)}].push_back(
          {int(i), v});
    }
  }
  for (const auto& [key, list] : at)
    for (size_t k = 1; k < list.size(); ++k)
      p.stitches.push_back({list[k - 1].first, list[k - 1].second, list[k].first, list[k].second});
  p.material = o.material;
  p.pressure = o.pressure;
  return p;
}

}  // namespace

const std::vector<std::string>& exampleNames() {
  static const std::vector<std::string> names = {"mylar",           "pillow", "gusset-pillow", "ring", "letter-L",
                                                 "letter-C",        "star",   "heart",         "cube", "sphere3",
                                                 "sphere3-internal"};
  return names;
}

Pattern examplePattern(const std::string& name, const ExampleOptions& o) {
  if (!(o.triangles >= 24 && o.triangles <= 2'000'000))
    throw Error("example.bad-value", "Choose between 24 and 2,000,000 triangles.");
  if (!(o.size > 0 && std::isfinite(o.size))) throw Error("example.bad-value", "The size must be positive.");
  if (name == "mylar") {
    const int K = std::max(2, int(std::lround(std::sqrt(o.triangles / 12.0))));
    return twoSided(disc(o.size, K), o);
  }
  if (name == "pillow") {
    // An even number of cells puts a diagonal through every corner; otherwise a corner triangle would have
    // all three corners on the seam and be sewn face to face with its twin.
    if (!(o.aspect >= 1 && o.aspect <= 100)) throw Error("example.bad-value", "Choose a pillow aspect from 1 to 100.");
    const int nx = std::max(2, 2 * int(std::lround(std::sqrt(o.triangles / (16.0 * o.aspect)))));
    const int ny = std::max(2, 2 * int(std::lround(o.aspect * nx / 2)));  // square cells
    return twoSided(rectangle(o.size, o.aspect * o.size, nx, ny), o);
  }
  if (name == "gusset-pillow") {
    // Front and back `size` by aspect x size, joined by a strip a quarter of `size` wide sewn around both
    // (its two ends sewn together): square cells on the faces, the strip's columns at their outline points.
    if (!(o.aspect >= 1 && o.aspect <= 100)) throw Error("example.bad-value", "Choose a pillow aspect from 1 to 100.");
    const double W = o.size, g = 0.25 * o.size;
    const double h = std::sqrt(2 * (2 * W * W * o.aspect + 2 * W * (1 + o.aspect) * g) / o.triangles);  // 2 per cell
    const int nx = std::max(2, 2 * int(std::lround(W / h / 2)));
    const int ny = std::max(2, 2 * int(std::lround(o.aspect * nx / 2)));
    const int rows = std::max(2, 2 * int(std::lround(g / h / 2)));
    // Square cells, the length rounded to whole cells, so that the strip's columns meet the faces' outline points.
    const double cell = W / nx, L = ny * cell;
    const int columns = 2 * (nx + ny);
    const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
    std::vector<PlacedPanel> placed = {{rectangle(W, L, nx, ny), inPlane(0.5 * g * Z, X, Y)},
                                       {rectangle(W, L, nx, ny), inPlane(-0.5 * g * Z, X, -Y)}};
    placed[1].panel.name = "back";
    // The strip goes around counterclockwise seen from the front, from the corner (-W/2, -L/2); its columns
    // are `cell` apart, as the faces' outline points.
    Panel strip = rectangle(columns * cell, g, columns, rows);
    strip.name = "gusset";
    const auto around = [=](const Eigen::Vector2d& q) {
      double s = q.x() + columns * cell / 2;
      const double sides[4] = {W, L, W, L};
      const Eigen::Vector2d starts[4] = {{-W / 2, -L / 2}, {W / 2, -L / 2}, {W / 2, L / 2}, {-W / 2, L / 2}};
      const Eigen::Vector2d along[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
      int k = 0;
      while (k < 3 && s > sides[k]) s -= sides[k++];
      const Eigen::Vector2d xy = starts[k] + std::min(s, sides[k]) * along[k];
      return Eigen::Vector3d(xy.x(), xy.y(), q.y());
    };
    placed.push_back({strip, around});
    return sewnWherePanelsMeet(placed, o.size, o);
  }
  if (name == "cube") {
    // Six squares of side `size`, each n by n square cells (n even: a diagonal through every corner).
    const int n = std::max(2, 2 * int(std::lround(std::sqrt(o.triangles / 12.0) / 2)));
    const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
    const double c = o.size / 2;
    const std::vector<std::array<Eigen::Vector3d, 3>> faces = {{c * X, Y, Z},  {-c * X, Z, Y}, {c * Y, Z, X},
                                                               {-c * Y, X, Z}, {c * Z, X, Y},  {-c * Z, Y, X}};
    std::vector<PlacedPanel> placed;
    for (size_t f = 0; f < faces.size(); ++f) {
      placed.push_back({rectangle(o.size, o.size, n, n), inPlane(faces[f][0], faces[f][1], faces[f][2])});
      placed.back().panel.name = "face " + std::to_string(f + 1);
    }
    return sewnWherePanelsMeet(placed, o.size, o);
  }
  if (name == "ring") {
    // A flat ring (a foil "O", a swim ring), outer radius `size`, hole half as wide.
    const double a = o.size, b = 0.5 * o.size;
    const double h = std::sqrt(2 * 4 * M_PI * (a * a - b * b) / (std::sqrt(3.0) * o.triangles));
    return twoSided(annulus(a, b, h), o);
  }
  if (name == "letter-L" || name == "letter-C" || name == "star" || name == "heart") {
    // Outlines `size` high: an L with arms a third as thick as long, a C (a ring 0.55 size thick cut open over
    // 90 degrees), a five-pointed star (inner radius 0.45 of the outer), a heart.
    const double s = o.size;
    std::vector<Eigen::Vector2d> pts;
    std::vector<int> corners;
    if (name == "letter-L") {
      pts = {{0, 0}, {0.7 * s, 0}, {0.7 * s, s / 3}, {s / 3, s / 3}, {s / 3, s}, {0, s}};
      for (int i = 0; i < 6; ++i) corners.push_back(i);
    } else if (name == "letter-C") {
      const double a0 = M_PI / 4, a1 = 7 * M_PI / 4;
      appendArc(pts, s / 2, a0, a1, 60);
      corners = {0, 60, 61};
      appendArc(pts, 0.225 * s, a1, a0, 30);
      corners.push_back(int(pts.size()) - 1);
    } else if (name == "star") {
      for (int k = 0; k < 10; ++k) {
        const double a = M_PI / 2 + M_PI * k / 5, r = (k % 2 ? 0.45 : 1.0) * s / 2;
        corners.push_back(k);
        pts.push_back(r * Eigen::Vector2d(std::cos(a), std::sin(a)));
      }
    } else {
      // x = 16 sin^3 t, y = 13 cos t - 5 cos 2t - 2 cos 3t - cos 4t (about 34 across, 29 high), clockwise in t.
      for (int k = 0; k < 200; ++k) {
        const double t = -2 * M_PI * k / 200;
        pts.push_back(s / 30 *
                      Eigen::Vector2d(16 * std::pow(std::sin(t), 3),
                                      13 * std::cos(t) - 5 * std::cos(2 * t) - 2 * std::cos(3 * t) - std::cos(4 * t)));
      }
      corners = {0, 100};  // the dip at the top and the point at the bottom
    }
    return outlinePair(toPoints(pts), corners, o);
  }
  if (name == "sphere3" || name == "sphere3-internal") {
    const int columns = std::max(3, int(std::lround(std::sqrt(M_PI * o.triangles / 8.0))));
    Pattern p;
    std::vector<std::pair<int, int>> sides;
    for (int g = 0; g < 3; ++g) {
      sides.clear();
      p.panels.push_back(gore(o.size, columns, sides));
      p.panels.back().name = "gore " + std::to_string(g + 1);
    }
    // The top side of gore g is sewn to the bottom side of gore g+1, column by column (equal lengths by
    // symmetry); the tips of all three gores meet at the poles.
    for (int g = 0; g < 3; ++g)
      for (const auto& [bottom, top] : sides) p.stitches.push_back({g, top, (g + 1) % 3, bottom});
    if (name == "sphere3-internal") {
      // An internal connection: a narrower gore inside, sewn to the seams gore 1|2 and gore 2|3 column by
      // column, pulls them together (a crease along the middle of gore 2).
      std::vector<std::pair<int, int>> inner;
      p.panels.push_back(gore(0.6 * o.size, columns, inner));
      p.panels.back().name = "internal";
      p.panels.back().internal = true;
      p.panels.back().vertices.col(0) /= 0.6;  // full meridian length, 60 % of the width
      for (size_t k = 0; k < inner.size(); ++k) {
        p.stitches.push_back({3, inner[k].first, 0, sides[k].second});
        p.stitches.push_back({3, inner[k].second, 1, sides[k].second});
      }
    }
    p.material = o.material;
    p.pressure = o.pressure;
    return p;
  }
  throw Error("example.unknown",
              "There is no example called '" + name +
                  "' (try mylar, pillow, gusset-pillow, ring, letter-L, letter-C, star, heart, cube, sphere3 or "
                  "sphere3-internal).");
}

MylarShape measureMylar(const SewnMesh& mesh, const Vertices& x) {
  const Eigen::Vector3d top = x.row(mesh.simVertex(0, 0)), bottom = x.row(mesh.simVertex(1, 0));
  const Eigen::Vector3d axis = (top - bottom).normalized();
  MylarShape s;
  s.poleThickness = (top - bottom).norm();
  Eigen::Vector3d rimCentre = Eigen::Vector3d::Zero();
  int n = 0;
  for (int v = 0; v < mesh.numVertices; ++v)
    if (mesh.stitchedCount[v] >= 2) rimCentre += x.row(v).transpose(), ++n;
  if (n == 0) return s;
  rimCentre /= n;
  const Eigen::Vector3d mid = bottom + (rimCentre - bottom).dot(axis) * axis;  // on the axis, in the rim plane
  for (int v = 0; v < mesh.numVertices; ++v) {
    if (mesh.stitchedCount[v] < 2) continue;
    const Eigen::Vector3d d = x.row(v).transpose() - mid;
    s.rimRadius += (d - d.dot(axis) * axis).norm() / n;
  }
  double sum[2] = {0, 0};
  int count[2] = {0, 0};
  for (int v = 0; v < mesh.numVertices; ++v) {
    const Eigen::Vector3d d = x.row(v).transpose() - mid;
    const double z = d.dot(axis), rho = (d - z * axis).norm() / s.rimRadius;
    if (rho < 0.15 || rho > 0.3) continue;
    const int side = z > 0 ? 0 : 1;
    sum[side] += std::abs(z) + s.rimRadius * rho * rho * rho / 3;
    ++count[side];
  }
  if (count[0] && count[1]) s.thickness = sum[0] / count[0] + sum[1] / count[1];
  return s;
}

}  // namespace billow
