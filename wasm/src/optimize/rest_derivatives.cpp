#include "optimize/rest_derivatives.hpp"

#include "simulate/enclosed_volume.hpp"

namespace billow {

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// First-order dual number over the six rest coordinates of one triangle.
struct D6 {
  double v = 0;
  Vector6d d = Vector6d::Zero();
};
D6 operator+(const D6& a, const D6& b) { return {a.v + b.v, a.d + b.d}; }
D6 operator-(const D6& a, const D6& b) { return {a.v - b.v, a.d - b.d}; }
D6 operator*(const D6& a, const D6& b) { return {a.v * b.v, a.v * b.d + b.v * a.d}; }
D6 operator*(double s, const D6& a) { return {s * a.v, s * a.d}; }
D6 var(double v, int i) {
  D6 r{v, Vector6d::Zero()};
  r.d[i] = 1;
  return r;
}

// Per-triangle view of the pattern: rest corners and simulation corners.
template <class F>
void forEachElement(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X, F&& fn) {
  const std::vector<int> start = panelTriangleStart(pattern);
  for (size_t p = 0; p < pattern.panels.size(); ++p) {
    const Panel& panel = pattern.panels[p];
    for (int k = 0; k < panel.triangles.rows(); ++k) {
      const int t = start[p] + k;
      int gid[3];
      Eigen::Vector2d R[3];
      for (int c = 0; c < 3; ++c) {
        gid[c] = mesh.panelVertexStart[p] + panel.triangles(k, c);
        R[c] = X.segment<2>(2 * gid[c]);
      }
      fn(t, gid, R);
    }
  }
}

// One element's share of the products with dg/dX, for sewn vertices v and panel vertices gid; J() gives its 9 x 6
// block and is only asked for where the element's part of lambda (dX) is not zero.
template <class Block>
void addElementTransposedProduct(const int* v, const int* gid, const Eigen::VectorXd& lambda, Block&& J,
                                 Eigen::VectorXd& out) {
  Vector9d l;
  for (int c = 0; c < 3; ++c) l.segment<3>(3 * c) = lambda.segment<3>(3 * v[c]);
  if (l.isZero(0)) return;
  const Eigen::Matrix<double, 6, 1> r = J().transpose() * l;
  for (int c = 0; c < 3; ++c) out.segment<2>(2 * gid[c]) += r.segment<2>(2 * c);
}
template <class Block>
void addElementProduct(const int* v, const int* gid, const Eigen::VectorXd& dX, Block&& J, Eigen::VectorXd& out) {
  Vector6d d;
  for (int c = 0; c < 3; ++c) d.segment<2>(2 * c) = dX.segment<2>(2 * gid[c]);
  if (d.isZero(0)) return;
  const Vector9d r = J() * d;
  for (int c = 0; c < 3; ++c) out.segment<3>(3 * v[c]) += r.segment<3>(3 * c);
}

}  // namespace

Vector9d membraneElementRestJacobian(const Eigen::Vector2d& X0, const Eigen::Vector2d& X1, const Eigen::Vector2d& X2,
                                     const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                                     const MembraneMaterial& material, Matrix96d* dGradDX) {
  // Dm = [X1 - X0, X2 - X0] and its inverse M, area A = det(Dm) / 2.
  const D6 a = var(X1.x(), 2) - var(X0.x(), 0), b = var(X2.x(), 4) - var(X0.x(), 0);
  const D6 c = var(X1.y(), 3) - var(X0.y(), 1), d = var(X2.y(), 5) - var(X0.y(), 1);
  const D6 det = a * d - b * c;
  const D6 inv{1.0 / det.v, (-1.0 / (det.v * det.v)) * det.d};
  const D6 M[2][2] = {{d * inv, D6{} - b * inv}, {D6{} - c * inv, a * inv}};
  const D6 area = 0.5 * det;
  Eigen::Matrix<double, 3, 2> Ds;
  Ds.col(0) = x1 - x0;
  Ds.col(1) = x2 - x0;
  // F = Ds M (3x2), c = (|F0|^2, |F1|^2, F0.F1).
  D6 F[3][2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) F[i][j] = Ds(i, 0) * M[0][j] + Ds(i, 1) * M[1][j];
  D6 cg[3];
  for (int i = 0; i < 3; ++i) {
    cg[0] = cg[0] + F[i][0] * F[i][0];
    cg[1] = cg[1] + F[i][1] * F[i][1];
    cg[2] = cg[2] + F[i][0] * F[i][1];
  }
  const Density den = relaxedDensity(Eigen::Vector3d(cg[0].v, cg[1].v, cg[2].v), material.kappa(), material.band);
  D6 S[3];  // dpsi/dc as duals: the Hessian in c carries the X dependence
  for (int i = 0; i < 3; ++i) {
    S[i].v = den.grad[i];
    for (int j = 0; j < 3; ++j) S[i].d += den.hess(i, j) * cg[j].d;
  }
  const D6 scale = material.thickness * area;
  // P = dW/dF: P0 = hA (2 S0 F0 + S2 F1), P1 = hA (2 S1 F1 + S2 F0); dW/dDs = P M^T.
  Vector9d grad;
  Matrix96d J;
  for (int i = 0; i < 3; ++i) {
    const D6 P0 = scale * (2.0 * (S[0] * F[i][0]) + S[2] * F[i][1]);
    const D6 P1 = scale * (2.0 * (S[1] * F[i][1]) + S[2] * F[i][0]);
    const D6 g1 = P0 * M[0][0] + P1 * M[0][1];  // column 0 of P M^T: corner 1
    const D6 g2 = P0 * M[1][0] + P1 * M[1][1];  // corner 2
    grad[3 + i] = g1.v, grad[6 + i] = g2.v, grad[i] = -(g1.v + g2.v);
    J.row(3 + i) = g1.d.transpose(), J.row(6 + i) = g2.d.transpose(), J.row(i) = -(g1.d + g2.d).transpose();
  }
  if (dGradDX) *dGradDX = J;
  return grad;
}

Eigen::VectorXd packPattern(const Pattern& pattern) {
  long n = 0;
  for (const Panel& p : pattern.panels) n += p.vertices.rows();
  Eigen::VectorXd X(2 * n);
  long k = 0;
  for (const Panel& p : pattern.panels)
    for (int v = 0; v < p.vertices.rows(); ++v, ++k) X.segment<2>(2 * k) = p.vertices.row(v).transpose();
  return X;
}

void unpackPattern(const Eigen::VectorXd& X, Pattern& pattern) {
  long k = 0;
  for (Panel& p : pattern.panels)
    for (int v = 0; v < p.vertices.rows(); ++v, ++k) p.vertices.row(v) = X.segment<2>(2 * k).transpose();
}

std::vector<int> panelTriangleStart(const Pattern& pattern) {
  std::vector<int> start{0};
  for (const Panel& p : pattern.panels) start.push_back(start.back() + static_cast<int>(p.triangles.rows()));
  return start;
}

Eigen::SparseMatrix<double> assembleStiffness(const SewnMesh& mesh, const Vertices& x, const MembraneMaterial& material,
                                              double pressure, const SeamRods* rods) {
  const int n = 3 * mesh.numVertices;
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(size_t(mesh.numTriangles()) * 2 * 81);
  ElementOptions exact;
  exact.projectHessian = false;  // the adjoint needs the true Hessian
  Vector9d g;
  Matrix9d H, HV;
  for (int t = 0; t < mesh.numTriangles(); ++t) {
    const int v[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    const Eigen::Vector3d x0 = x.row(v[0]), x1 = x.row(v[1]), x2 = x.row(v[2]);
    membraneElement(mesh.rest[t], x0, x1, x2, material, exact, &g, &H);
    if (mesh.outer[t]) {
      triangleVolumeDerivatives(x0, x1, x2, nullptr, &HV);
      H -= pressure * HV;  // Pi = W - p V
    }
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) trip.emplace_back(3 * v[a] + i, 3 * v[b] + j, H(3 * a + i, 3 * b + j));
  }
  if (rods) rods->forEachHessianEntry([&](int r, int c, double value) { trip.emplace_back(r, c, value); });
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(trip.begin(), trip.end());
  return K;
}

Eigen::VectorXd equilibriumGradient(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X,
                                    const Vertices& x, const MembraneMaterial& material, double pressure) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * mesh.numVertices);
  forEachElement(mesh, pattern, X, [&](int t, const int*, const Eigen::Vector2d* R) {
    const int v[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    const Eigen::Vector3d x0 = x.row(v[0]), x1 = x.row(v[1]), x2 = x.row(v[2]);
    Vector9d ge = membraneElementRestJacobian(R[0], R[1], R[2], x0, x1, x2, material, nullptr);
    if (mesh.outer[t]) {
      Vector9d gv;
      triangleVolumeDerivatives(x0, x1, x2, &gv, nullptr);
      ge -= pressure * gv;
    }
    for (int c = 0; c < 3; ++c) g.segment<3>(3 * v[c]) += ge.segment<3>(3 * c);
  });
  return g;
}

void addRestGradientProduct(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X, const Vertices& x,
                            const Eigen::VectorXd& lambda, const MembraneMaterial& material, Eigen::VectorXd& out) {
  Matrix96d J;
  forEachElement(mesh, pattern, X, [&](int t, const int* gid, const Eigen::Vector2d* R) {
    const int v[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    addElementTransposedProduct(
        v, gid, lambda,
        [&]() -> const Matrix96d& {
          membraneElementRestJacobian(R[0], R[1], R[2], x.row(v[0]), x.row(v[1]), x.row(v[2]), material, &J);
          return J;
        },
        out);
  });
}

void addRestJacobianProduct(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X, const Vertices& x,
                            const Eigen::VectorXd& dX, const MembraneMaterial& material, Eigen::VectorXd& out) {
  Matrix96d J;
  forEachElement(mesh, pattern, X, [&](int t, const int* gid, const Eigen::Vector2d* R) {
    const int v[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    addElementProduct(
        v, gid, dX,
        [&]() -> const Matrix96d& {
          membraneElementRestJacobian(R[0], R[1], R[2], x.row(v[0]), x.row(v[1]), x.row(v[2]), material, &J);
          return J;
        },
        out);
  });
}

RestJacobian::RestJacobian(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X, const Vertices& x,
                           const MembraneMaterial& material) {
  elements_.reserve(size_t(mesh.numTriangles()));
  forEachElement(mesh, pattern, X, [&](int t, const int* gid, const Eigen::Vector2d* R) {
    Element e;
    for (int c = 0; c < 3; ++c) e.vertex[c] = mesh.triangles(t, c), e.pattern[c] = gid[c];
    membraneElementRestJacobian(R[0], R[1], R[2], x.row(e.vertex[0]), x.row(e.vertex[1]), x.row(e.vertex[2]), material,
                                &e.J);
    elements_.push_back(e);
  });
}

void RestJacobian::addTransposedProduct(const Eigen::VectorXd& lambda, Eigen::VectorXd& out) const {
  for (const Element& e : elements_)
    addElementTransposedProduct(
        e.vertex, e.pattern, lambda, [&]() -> const Matrix96d& { return e.J; }, out);
}

void RestJacobian::addProduct(const Eigen::VectorXd& dX, Eigen::VectorXd& out) const {
  for (const Element& e : elements_)
    addElementProduct(
        e.vertex, e.pattern, dX, [&]() -> const Matrix96d& { return e.J; }, out);
}

double seamRodCoefficientAt(const SewnMesh& mesh, const Pattern& pattern, const Eigen::VectorXd& X, double pressure,
                            double beta, Eigen::VectorXd* dcdX) {
  double area = 0, edges = 0;
  Eigen::VectorXd dArea, dEdges;
  if (dcdX) dArea.setZero(X.size()), dEdges.setZero(X.size());
  forEachElement(mesh, pattern, X, [&](int t, const int* gid, const Eigen::Vector2d* R) {
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector2d e = R[(c + 1) % 3] - R[c];
      const double l = e.norm();
      edges += l;
      if (dcdX && l > 0) dEdges.segment<2>(2 * gid[(c + 1) % 3]) += e / l, dEdges.segment<2>(2 * gid[c]) -= e / l;
    }
    if (!mesh.outer[t]) return;
    const Eigen::Vector2d u = R[1] - R[0], v = R[2] - R[0];
    area += 0.5 * (u.x() * v.y() - u.y() * v.x());
    if (dcdX)  // d(area)/dR_c = perp(R_{c+2} - R_{c+1}) / 2 for a counterclockwise triangle
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector2d w = R[(c + 2) % 3] - R[(c + 1) % 3];
        dArea.segment<2>(2 * gid[c]) += 0.5 * Eigen::Vector2d(-w.y(), w.x());
      }
  });
  const int triangles = mesh.numTriangles();
  const double l = triangles ? edges / (3.0 * triangles) : 0;
  const double c = seamRodCoefficient(area, l, pressure, beta);
  if (dcdX) {
    // c = beta p (A / 4 pi)^2 / l^3: dc = c (2 dA / A - 3 dl / l), l = edges / 3T.
    dcdX->setZero(X.size());
    if (c > 0) *dcdX = c * (2 / area * dArea - 3 / edges * dEdges);
  }
  return c;
}

namespace {
// dS/dx of the rods' energy per unit coefficient.
Eigen::VectorXd rodShapeGradient(const SeamRods& rods, const Vertices& x) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * x.rows());
  if (rods.empty()) return g;
  SeamRods unit = rods;
  unit.coefficient = 1;
  unit.addGradient(x, g);
  return g;
}
}  // namespace

void addRodGradientProduct(const SeamRods& rods, const Vertices& x, const Eigen::VectorXd& dcdX,
                           const Eigen::VectorXd& lambda, Eigen::VectorXd& out) {
  if (rods.empty()) return;
  out += lambda.dot(rodShapeGradient(rods, x)) * dcdX;
}

void addRodJacobianProduct(const SeamRods& rods, const Vertices& x, const Eigen::VectorXd& dcdX,
                           const Eigen::VectorXd& dX, Eigen::VectorXd& out) {
  if (rods.empty()) return;
  out += dcdX.dot(dX) * rodShapeGradient(rods, x);
}

}  // namespace billow
