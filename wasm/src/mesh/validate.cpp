// Target validation (see validate.hpp). Topology is read from the sorted list of half-edges:
// an undirected edge used once is a boundary, twice a manifold edge, more often a non-manifold edge.
#include "mesh/validate.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <queue>
#include <set>

#include "mesh/location.hpp"
#include "util/text.hpp"

namespace billow {

namespace {

struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

struct HalfEdge {
  uint64_t key;  // undirected edge (min, max)
  int face;
  int local;  // edge `local` runs from corner local to corner (local + 1) % 3
};

class Validator {
 public:
  Validator(TriMesh& mesh, const ValidationOptions& options) : m_(mesh), opt_(options) {}

  ValidationReport run() {
    auto& st = r_.stats;
    st.triangles = m_.numTriangles();
    if (m_.numTriangles() == 0) {
      add("mesh.empty", "error", "The file contains no triangles, so there is no shape to design on.", 0);
      return finish();
    }
    if (m_.numTriangles() > opt_.maxTriangles) {
      add("mesh.too-large", "error", tooLargeMessage("The mesh", m_.numTriangles(), opt_.maxTriangles, "triangles"),
          m_.numTriangles());
      return finish();
    }
    if (!checkNumbers()) return finish();
    computeBox();
    const double diag = (st.bboxMax - st.bboxMin).norm();
    if (!(diag > 0) || !std::isfinite(diag)) {
      add("mesh.no-size", "error", "All the vertices are at the same point: the shape has no size.", 0);
      return finish();
    }
    checkTriangles(diag);
    buildEdges();
    edgeIssuesFrom_ = r_.issues.size();
    checkEdges();
    checkVertexFans();
    countComponents();
    if (nonManifoldEdges_ == 0) fixOrientation();
    computeMeasures();
    checkVolume(diag);
    computeGenus();
    return finish();
  }

 private:
  TriMesh& m_;
  const ValidationOptions& opt_;
  ValidationReport r_;
  std::vector<HalfEdge> half_;
  std::vector<std::array<int, 3>> pairs_;  // manifold edges: face a, face b, 1 if both run the same way
  std::vector<int> referenced_;
  int nonManifoldEdges_ = 0, nonManifoldVertices_ = 0, inconsistentEdges_ = 0;
  size_t edgeIssuesFrom_ = 0;  // where checkEdges' issues start, so that gathering the edges again replaces them
  bool orientable_ = true;

  Eigen::Vector3d centroid(int f) const {
    return (m_.V.row(m_.F(f, 0)) + m_.V.row(m_.F(f, 1)) + m_.V.row(m_.F(f, 2))).transpose() / 3.0;
  }
  std::string where(const Eigen::Vector3d& p) const { return describeLocation(p, r_.stats.bboxMin, r_.stats.bboxMax); }

  void add(const std::string& code, const std::string& severity, const std::string& message, int count,
           const Eigen::Vector3d* at = nullptr) {
    MeshIssue issue{code, severity, message, count, at != nullptr, at ? *at : Eigen::Vector3d::Zero()};
    r_.issues.push_back(issue);
  }

  ValidationReport finish() {
    static const std::array<std::string, 3> order = {"error", "warning", "notice"};
    std::stable_sort(r_.issues.begin(), r_.issues.end(), [](const MeshIssue& a, const MeshIssue& b) {
      return std::find(order.begin(), order.end(), a.severity) < std::find(order.begin(), order.end(), b.severity);
    });
    r_.ok = std::none_of(r_.issues.begin(), r_.issues.end(), [](const MeshIssue& i) { return i.severity == "error"; });
    if (r_.ok && opt_.guessUp) r_.stats.standing = guessUp(m_);
    return r_;
  }

  bool checkNumbers() {
    const int nV = m_.numVertices();
    int badIndex = 0, notFinite = 0;
    for (int f = 0; f < m_.numTriangles(); ++f)
      for (int c = 0; c < 3; ++c)
        if (m_.F(f, c) < 0 || m_.F(f, c) >= nV) ++badIndex;
    if (badIndex > 0) {
      add("mesh.bad-index", "error",
          "The file refers to vertices that do not exist (" + plural(badIndex, "bad index", "bad indices") + " among " +
              std::to_string(nV) + " vertices). The file is damaged; export it again.",
          badIndex);
      return false;
    }
    referenced_.assign(nV, 0);
    for (int f = 0; f < m_.numTriangles(); ++f)
      for (int c = 0; c < 3; ++c) referenced_[m_.F(f, c)] = 1;
    for (int v = 0; v < nV; ++v)
      if (referenced_[v] && !m_.V.row(v).allFinite()) ++notFinite;
    if (notFinite > 0) {
      add("mesh.not-finite", "error",
          plural(notFinite, "vertex has", "vertices have") +
              " invalid coordinates (not a number or infinite). The file is damaged; export it again.",
          notFinite);
      return false;
    }
    r_.stats.vertices = static_cast<int>(std::count(referenced_.begin(), referenced_.end(), 1));
    if (r_.stats.vertices < nV)
      add("mesh.unused-vertices", "notice",
          plural(nV - r_.stats.vertices, "vertex is", "vertices are") + " not used by any triangle and " +
              (nV - r_.stats.vertices == 1 ? "was" : "were") + " ignored.",
          nV - r_.stats.vertices);
    return true;
  }

  void computeBox() {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = Eigen::Vector3d::Constant(-INFINITY);
    for (int v = 0; v < m_.numVertices(); ++v) {
      if (!referenced_[v]) continue;
      lo = lo.cwiseMin(m_.V.row(v).transpose());
      hi = hi.cwiseMax(m_.V.row(v).transpose());
    }
    r_.stats.bboxMin = lo;
    r_.stats.bboxMax = hi;
  }

  void checkTriangles(double diag) {
    int degenerate = 0, duplicate = 0, firstDegenerate = -1;
    Eigen::Vector3d firstDuplicate = Eigen::Vector3d::Zero();
    std::vector<char> repeats(static_cast<size_t>(m_.numTriangles()), 0);  // the same corners as a triangle before it
    std::set<std::array<int, 3>> seen;
    for (int f = 0; f < m_.numTriangles(); ++f) {
      const Eigen::Vector3d a = m_.V.row(m_.F(f, 0)), b = m_.V.row(m_.F(f, 1)), c = m_.V.row(m_.F(f, 2));
      const double area = 0.5 * (b - a).cross(c - a).norm();
      const bool repeated = m_.F(f, 0) == m_.F(f, 1) || m_.F(f, 1) == m_.F(f, 2) || m_.F(f, 0) == m_.F(f, 2);
      if (repeated || area < opt_.degenerateAreaRatio * diag * diag) {
        if (degenerate++ == 0) firstDegenerate = f;
      }
      std::array<int, 3> k = {m_.F(f, 0), m_.F(f, 1), m_.F(f, 2)};
      std::sort(k.begin(), k.end());
      if (!seen.insert(k).second) {
        if (duplicate++ == 0) firstDuplicate = centroid(f);
        repeats[size_t(f)] = 1;
      }
    }
    if (degenerate > 0) {
      const Eigen::Vector3d p = centroid(firstDegenerate);
      add("mesh.degenerate", "error",
          plural(degenerate, "triangle has", "triangles have") + " no area (degenerate), the first " + where(p) +
              ". Remove them, for example with 'Merge by Distance' in Blender, and load the mesh again.",
          degenerate, &p);
    }
    if (duplicate > 0) {
      // A triangle twice over is a file's slip (an export that wrote a face again), not a shape: the copies are
      // left out, keeping the first of each and the order of the rest, so every load of the file numbers its
      // faces alike.
      Triangles kept(m_.numTriangles() - duplicate, 3);
      for (int f = 0, row = 0; f < m_.numTriangles(); ++f)
        if (!repeats[size_t(f)]) kept.row(row++) = m_.F.row(f);
      m_.F = std::move(kept);
      r_.stats.triangles = m_.numTriangles();
      r_.modified = true;
      add("mesh.duplicate", "notice",
          plural(duplicate, "triangle appeared", "triangles appeared") + " twice, the first " + where(firstDuplicate) +
              ": the " + (duplicate == 1 ? "copy was" : "copies were") + " left out.",
          duplicate, &firstDuplicate);
    }
  }

  void buildEdges() {
    half_.reserve(3 * static_cast<size_t>(m_.numTriangles()));
    for (int f = 0; f < m_.numTriangles(); ++f)
      for (int e = 0; e < 3; ++e) {
        const int a = m_.F(f, e), b = m_.F(f, (e + 1) % 3);
        if (a != b) half_.push_back({edgeKey(a, b), f, e});
      }
    std::sort(half_.begin(), half_.end(),
              [](const HalfEdge& x, const HalfEdge& y) { return x.key != y.key ? x.key < y.key : x.face < y.face; });
  }

  // Visits each group of half-edges with the same undirected edge: [begin, end).
  template <class Fn>
  void forEachEdge(Fn fn) const {
    for (size_t i = 0; i < half_.size();) {
      size_t j = i + 1;
      while (j < half_.size() && half_[j].key == half_[i].key) ++j;
      fn(i, j);
      i = j;
    }
  }

  int from(const HalfEdge& h) const { return m_.F(h.face, h.local); }

  void checkEdges() {
    auto& st = r_.stats;
    std::vector<std::pair<int, int>> boundary;
    int firstNonManifold = -1;
    forEachEdge([&](size_t i, size_t j) {
      ++st.edges;
      const size_t k = j - i;
      if (k == 1) {
        boundary.push_back({from(half_[i]), m_.F(half_[i].face, (half_[i].local + 1) % 3)});
      } else if (k == 2) {
        const bool same = from(half_[i]) == from(half_[i + 1]);
        pairs_.push_back({half_[i].face, half_[i + 1].face, same ? 1 : 0});
        if (same) ++inconsistentEdges_;
      } else if (nonManifoldEdges_++ == 0) {
        firstNonManifold = half_[i].face;
      }
    });
    st.boundaryEdges = static_cast<int>(boundary.size());
    if (!boundary.empty()) reportHoles(boundary);
    if (nonManifoldEdges_ > 0) {
      const Eigen::Vector3d p = centroid(firstNonManifold);
      add("mesh.non-manifold-edge", "error",
          plural(nonManifoldEdges_, "edge is", "edges are") +
              " shared by more than two triangles (non-manifold), the first " + where(p) +
              ". On a closed surface every edge joins exactly two triangles.",
          nonManifoldEdges_, &p);
    }
  }

  void reportHoles(const std::vector<std::pair<int, int>>& boundary) {
    DisjointSets loops(m_.numVertices());
    for (const auto& [a, b] : boundary) loops.unite(a, b);
    std::vector<double> length(m_.numVertices(), 0.0);
    std::vector<Eigen::Vector3d> sum(m_.numVertices(), Eigen::Vector3d::Zero());
    std::vector<int> count(m_.numVertices(), 0);
    for (const auto& [a, b] : boundary) {
      const int root = loops.find(a);
      length[root] += (m_.V.row(a) - m_.V.row(b)).norm();
      sum[root] += m_.V.row(a).transpose();
      ++count[root];
    }
    int holes = 0, largest = -1;
    for (int v = 0; v < m_.numVertices(); ++v)
      if (count[v] > 0) {
        ++holes;
        if (largest < 0 || length[v] > length[largest]) largest = v;
      }
    r_.stats.holes = holes;
    const Eigen::Vector3d p = sum[largest] / count[largest];
    if (flatSheet()) {
      // Capping a flat sheet's outline would enclose nothing: what it wants is thickness, so no hole is offered to
      // close.
      add("mesh.flat-sheet", "error",
          "The mesh is a flat sheet with no thickness (" +
              plural(r_.stats.boundaryEdges, "boundary edge", "boundary edges") + " along " +
              plural(holes, "outline", "outlines") +
              "): a balloon needs a closed 3D shape to hold air. For a two-piece balloon of this outline, give the "
              "sheet thickness first (for example 'Solidify' in Blender, or extrude it) and load it again.",
          r_.stats.boundaryEdges, &p);
      return;
    }
    add("mesh.open", "error",
        "The mesh has " + plural(r_.stats.boundaryEdges, "boundary edge", "boundary edges") + " around " +
            plural(holes, "hole", "holes") + ": it must be closed to hold air. The largest hole is " + where(p) +
            ". Fill the holes (for example with 'Fill Holes' in MeshLab or Blender) and load it again.",
        r_.stats.boundaryEdges, &p);
  }

  // Every vertex within a millionth of the mesh's size of one plane (its best fit): a drawing's flat sheet, not a
  // shape.
  bool flatSheet() const {
    const Eigen::RowVector3d center = m_.V.colwise().mean();
    const Eigen::MatrixX3d centered = m_.V.rowwise() - center;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(centered.transpose() * centered);
    const double diag = (r_.stats.bboxMax - r_.stats.bboxMin).norm();
    return (centered * principal.eigenvectors().col(0)).cwiseAbs().maxCoeff() <= 1e-6 * diag;
  }

  // A vertex is manifold when its triangles form a single fan: corners at the vertex are joined
  // whenever their triangles share an edge through it. Where a vertex joins several fans of one piece (a tail tip
  // touching a leg at a point), each fan after the first gets a vertex of its own at the same place: the surface is
  // then manifold, still touching itself there. Fans of separate pieces stay an error: they are two shapes.
  void checkVertexFans() {
    DisjointSets corners(3 * m_.numTriangles()), pieces(m_.numTriangles());
    auto cornerAt = [&](const HalfEdge& h, int v) { return 3 * h.face + (from(h) == v ? h.local : (h.local + 1) % 3); };
    forEachEdge([&](size_t i, size_t j) {
      const int a = static_cast<int>(half_[i].key >> 32), b = static_cast<int>(half_[i].key & 0xffffffffu);
      for (size_t k = i + 1; k < j; ++k) {
        corners.unite(cornerAt(half_[i], a), cornerAt(half_[k], a));
        corners.unite(cornerAt(half_[i], b), cornerAt(half_[k], b));
        pieces.unite(half_[i].face, half_[k].face);
      }
    });
    std::vector<int> firstRoot(m_.numVertices(), -1), fans(m_.numVertices(), 0);
    std::vector<char> onePiece(m_.numVertices(), 1);
    for (int c = 0; c < 3 * m_.numTriangles(); ++c) {
      const int v = m_.F(c / 3, c % 3), root = corners.find(c);
      if (firstRoot[v] == -1) {
        firstRoot[v] = root;
        fans[v] = 1;
      } else if (firstRoot[v] != root) {
        fans[v] = 2;  // at least two fans; enough to know
        if (pieces.find(c / 3) != pieces.find(firstRoot[v] / 3)) onePiece[v] = 0;
      }
    }
    const bool split = nonManifoldEdges_ == 0;
    int first = -1, firstSplit = -1, splitCount = 0;
    std::map<int, int> vertexOfFan;  // a fan's root -> its own vertex, for the fans after a vertex's first
    for (int v = 0; v < m_.numVertices(); ++v) {
      if (fans[v] < 2) continue;
      if (split && onePiece[v]) {
        if (splitCount++ == 0) firstSplit = v;
      } else if (nonManifoldVertices_++ == 0) {
        first = v;
      }
    }
    if (splitCount > 0) {
      const Eigen::Vector3d p = m_.V.row(firstSplit);
      const int before = m_.numVertices();
      for (int c = 0; c < 3 * m_.numTriangles(); ++c) {
        const int v = m_.F(c / 3, c % 3), root = corners.find(c);
        if (v >= before || fans[v] < 2 || !onePiece[v] || root == firstRoot[v]) continue;
        auto [at, added] = vertexOfFan.try_emplace(root, m_.numVertices());
        if (added) {
          m_.V.conservativeResize(m_.numVertices() + 1, 3);
          m_.V.row(at->second) = m_.V.row(v);
        }
        m_.F(c / 3, c % 3) = at->second;
      }
      const int added = m_.numVertices() - before;
      referenced_.resize(static_cast<size_t>(m_.numVertices()), 1);
      r_.stats.vertices += added;
      r_.modified = true;
      // The corners changed: the edges are gathered again (the same ones, between other vertices), and their
      // issues (holes, non-manifold edges) said once.
      half_.clear(), pairs_.clear();
      r_.issues.resize(edgeIssuesFrom_);
      r_.stats.edges = 0, inconsistentEdges_ = 0, nonManifoldEdges_ = 0;
      buildEdges();
      checkEdges();
      add("mesh.pinch-split", "notice",
          plural(splitCount, "point where the surface touched itself", "points where the surface touched itself") +
              " (the first " + where(p) + ") " + (splitCount == 1 ? "was" : "were") +
              " given a vertex for each part that meets there, so that Billow can follow the surface; the shape is "
              "unchanged.",
          splitCount, &p);
    }
    if (nonManifoldVertices_ > 0) {
      const Eigen::Vector3d p = m_.V.row(first);
      add("mesh.non-manifold-vertex", "error",
          plural(nonManifoldVertices_, "vertex joins", "vertices join") +
              " parts of the surface that only touch at a point (non-manifold), the first " + where(p) +
              ". Separate or merge the parts there.",
          nonManifoldVertices_, &p);
    }
  }

  void countComponents() {
    DisjointSets faces(m_.numTriangles());
    forEachEdge([&](size_t i, size_t j) {
      for (size_t k = i + 1; k < j; ++k) faces.unite(half_[i].face, half_[k].face);
    });
    std::vector<int> size(m_.numTriangles(), 0);
    for (int f = 0; f < m_.numTriangles(); ++f) ++size[faces.find(f)];
    int components = 0, smallest = -1;
    for (int f = 0; f < m_.numTriangles(); ++f)
      if (size[f] > 0) {
        ++components;
        if (smallest < 0 || size[f] < size[smallest]) smallest = f;
      }
    r_.stats.components = components;
    if (components > 1) {
      const Eigen::Vector3d p = centroid(smallest);
      add("mesh.components", "error",
          "The mesh has " + std::to_string(components) +
              " separate pieces; Billow needs one closed shape. The smallest piece (" +
              plural(size[smallest], "triangle", "triangles") + ") is " + where(p) +
              ". Delete the extra pieces or join them into one surface.",
          components, &p);
    }
  }

  // Propagates one orientation over each component through its manifold edges; flips the minority.
  void fixOrientation() {
    if (inconsistentEdges_ == 0) return;
    const int nF = m_.numTriangles();
    std::vector<std::vector<std::pair<int, int>>> adjacent(nF);
    for (const auto& p : pairs_) {
      adjacent[p[0]].push_back({p[1], p[2]});
      adjacent[p[1]].push_back({p[0], p[2]});
    }
    std::vector<int> flip(nF, -1);
    std::vector<int> toFlip;
    int firstConflict = -1;
    for (int seed = 0; seed < nF; ++seed) {
      if (flip[seed] != -1) continue;
      std::vector<int> component{seed};
      flip[seed] = 0;
      std::queue<int> queue;
      queue.push(seed);
      while (!queue.empty()) {
        const int f = queue.front();
        queue.pop();
        for (const auto& [g, same] : adjacent[f]) {
          const int want = flip[f] ^ same;
          if (flip[g] == -1) {
            flip[g] = want;
            component.push_back(g);
            queue.push(g);
          } else if (flip[g] != want && firstConflict < 0) {
            firstConflict = f;
          }
        }
      }
      const auto flipped = std::count_if(component.begin(), component.end(), [&](int f) { return flip[f] == 1; });
      const int minority = 2 * flipped > static_cast<long>(component.size()) ? 0 : 1;
      for (int f : component)
        if (flip[f] == minority) toFlip.push_back(f);
    }
    if (firstConflict >= 0) {
      orientable_ = false;
      const Eigen::Vector3d p = centroid(firstConflict);
      add("mesh.non-orientable", "error",
          "The surface has no consistent inside and outside (like a Moebius strip), for example " + where(p) + ".", 1,
          &p);
      return;
    }
    for (int f : toFlip) std::swap(m_.F(f, 1), m_.F(f, 2));
    r_.modified = true;
    const Eigen::Vector3d p = centroid(toFlip.front());
    add("mesh.reoriented", "notice",
        plural(static_cast<int>(toFlip.size()), "triangle faced", "triangles faced") + " the wrong way (the first " +
            where(p) + "); Billow turned them around.",
        static_cast<int>(toFlip.size()), &p);
  }

  void computeMeasures() {
    auto& st = r_.stats;
    st.area = 0;
    st.volume = 0;
    for (int f = 0; f < m_.numTriangles(); ++f) {
      const Eigen::Vector3d a = m_.V.row(m_.F(f, 0)), b = m_.V.row(m_.F(f, 1)), c = m_.V.row(m_.F(f, 2));
      st.area += 0.5 * (b - a).cross(c - a).norm();
      st.volume += a.dot(b.cross(c)) / 6.0;
    }
  }

  bool closedManifold() const {
    return r_.stats.boundaryEdges == 0 && nonManifoldEdges_ == 0 && nonManifoldVertices_ == 0 && orientable_;
  }

  void checkVolume(double diag) {
    auto& st = r_.stats;
    if (!closedManifold()) return;
    if (std::abs(st.volume) < 1e-9 * diag * diag * diag) {
      add("mesh.flat", "error", "The shape encloses no volume (it is flat), so it cannot be inflated.", 0);
      return;
    }
    if (st.volume < 0 && st.components == 1) {
      for (int f = 0; f < m_.numTriangles(); ++f) std::swap(m_.F(f, 1), m_.F(f, 2));
      st.volume = -st.volume;
      r_.modified = true;
      add("mesh.inside-out", "notice",
          "The mesh was inside out (its triangles faced inward); Billow turned it the right way.", m_.numTriangles());
    }
  }

  void computeGenus() {
    auto& st = r_.stats;
    if (!closedManifold() || st.components != 1) return;
    const int chi = st.vertices - st.edges + st.triangles;
    st.genus = (2 - chi) / 2;
    if (st.genus > 0)
      add("mesh.genus", "warning",
          "The shape has " + plural(st.genus, "handle", "handles") + " (genus " + std::to_string(st.genus) +
              "). Every handle needs a seam around it before the surface can be cut into flat panels.",
          st.genus);
  }
};

}  // namespace

ValidationReport validateTarget(TriMesh& mesh, const ValidationOptions& options) {
  return Validator(mesh, options).run();
}

std::string toJson(const ValidationReport& report) {
  using nlohmann::json;
  const auto& st = report.stats;
  auto vec = [](const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); };
  json issues = json::array();
  for (const auto& i : report.issues) {
    json item = {{"code", i.code}, {"severity", i.severity}, {"message", i.message}, {"count", i.count}};
    if (i.hasLocation) item["location"] = vec(i.location);
    issues.push_back(item);
  }
  json j = {{"ok", report.ok},
            {"modified", report.modified},
            {"stats",
             {{"vertices", st.vertices},
              {"triangles", st.triangles},
              {"edges", st.edges},
              {"components", st.components},
              {"boundary_edges", st.boundaryEdges},
              {"holes", st.holes},
              {"genus", st.genus},
              {"bbox_min", vec(st.bboxMin)},
              {"bbox_max", vec(st.bboxMax)},
              {"area", st.area},
              {"volume", st.volume},
              {"up", toString(st.standing.up)},
              {"stands_y", st.standing.standsY},
              {"stands_z", st.standing.standsZ}}},
            {"issues", issues}};
  return j.dump();
}

}  // namespace billow
