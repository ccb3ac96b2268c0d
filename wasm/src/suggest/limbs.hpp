// A target's limbs (arms, legs, fingers, ears, tentacles) and where each joins the body, for layouts that seam
// around a limb's root and halve it along its length, as a pattern maker chalks a plush toy's (issue 27).
//
// Seen from a limb's tip, the surface within a geodesic distance r is a cap that grows along the limb as a tube:
// its rim keeps about the limb's girth P while r grows, so pi r / P, the cap's length over its width, climbs. Past
// the root the rim spreads over the body and the ratio falls. A tip whose ratio climbs past kLimbElongation is a
// limb's, and its root is where the ratio last stands near its highest (or nearer the tip, where that would overlap a
// more elongated limb): the rim there, a loop around the limb where it joins the body.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "mesh/tri_mesh.hpp"
#include "seams/plane_section.hpp"

namespace billow {

// A cap at least this much longer than wide is a limb (a bump or the end of a round body is wider than long).
constexpr double kLimbElongation = 1.5;

struct Limb {
  int tip = -1;  // the target vertex at its end
  // Per target vertex, linear over each face: negative on the limb, positive on the body (the distance from its tip
  // along the surface, less its root's); the root loop is where it is zero.
  Eigen::VectorXd level;
  SectionLoop rootLoop;
  // Per target face: 1 on the limb beyond its root loop, 2 where the root loop crosses (onLimb tells by the level), 0
  // elsewhere.
  std::vector<char> faces;
  // Through its length, its flattest direction the normal: the seam that halves it follows its outline seen along that
  // normal (or across, the next flattest direction, where that outline does not run round its tip).
  SectionPlane along;
  Eigen::Vector3d across = Eigen::Vector3d::UnitY();  // unit, across `along`'s normal
  Eigen::Vector3d center = Eigen::Vector3d::Zero();   // of its area
  double elongation = 0;                              // its cap's greatest length over width (pi r / P)
  double area = 0;                                    // [target units^2]
  double girth = 0;                                   // the root loop's length
};

// The limbs of a closed target, most elongated first; none overlaps another.
std::vector<Limb> findLimbs(const TriMesh& target);

// The limbs as a set that is its own mirror image across the plane {p[axis] = mid} of a mirror-symmetric target, in
// groups, most elongated first: each limb off the plane with its mirror image (its level and plane along it
// reflected), each on the plane (a tail) alone, its level made its own mirror image and halved along the plane.
std::vector<std::vector<Limb>> mirrorSymmetricLimbs(const TriMesh& target, const std::vector<Limb>& limbs, int axis,
                                                    double mid);

// The limb's level at the point p of target face f.
double limbLevel(const TriMesh& target, const Limb& limb, int face, const Eigen::Vector3d& p);

// Whether the point p of target face f lies on the limb.
bool onLimb(const TriMesh& target, const Limb& limb, int face, const Eigen::Vector3d& p);

}  // namespace billow
