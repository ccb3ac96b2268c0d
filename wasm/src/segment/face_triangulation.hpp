// Constrained triangulation of one target triangle that seams cross (segmentation, paper Sec. 5.2: "converting
// the user-provided seams ... into sets of edge vectors, defining a segmentation of the target mesh").
// Points are inserted by splitting, constraint segments recovered by edge flips (Sloan 1993, "A fast
// algorithm for generating constrained Delaunay triangulations"), then the rest is made Delaunay by Lawson
// flips so that the pieces of a face stay well shaped for flattening.
#pragma once
#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

namespace billow {

// pts: 2D points, the first three the triangle's corners (CCW); the others on its edges or inside, distinct.
// constraints: pairs of point indices that must become edges; they must not cross each other or pass
// through other points. Returns CCW triangles over pts. unrecovered, when given, counts constraints that
// could not be inserted (0 unless the input breaks the rules above).
std::vector<std::array<int, 3>> triangulateFace(const std::vector<Eigen::Vector2d>& pts,
                                                const std::vector<std::pair<int, int>>& constraints,
                                                int* unrecovered = nullptr);

}  // namespace billow
