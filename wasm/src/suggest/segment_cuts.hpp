// Cuts that open a segment that is not a disk, as a designer answers the segmentation's "add a seam from one loop to
// the other" and "add a seam across it": paths through the segment that join its seam loops (a tube, a part with
// holes), and loops around its handles (a skull's cheek arches, a mug's handle), whose two sides then bound the segment
// as two more loops each for the cuts to join. And a cut across a disk that would overlap itself when laid flat.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "segment/segmentation.hpp"

namespace billow {

// Paths through the inside of `segment` (on Segmentation::mesh) that join all its seam loops: loops - 1 of them, each
// the shortest between two loops not yet joined (two between the same loops would cut a piece off between them).
// Each is cut-mesh vertices from a vertex of one loop to a vertex of another, left from the side the segment lies on:
// from one side of a seam round a ring to its other side it ends where it began (none that would cut a piece off).
std::vector<std::vector<int>> cutsJoiningLoops(const Segmentation& segmentation, int segment);

// Loops through the inside of `segment` (on Segmentation::mesh, off its seams), one around each of its handles: of
// Erickson and Whittlesey's greedy systems of loops (2005) from `roots` roots spread over the segment, the shortest
// first, each apart from those taken, as long as all of them together leave the segment whole. Cut-mesh vertices in
// order, the first not repeated at the end; none when the segment has no handle, fewer than its genus where no more
// are found off its seams. None shorter than `minLength` [mesh units]: round a handle only a few of the panels' edges
// thick the seam would be a triangle or two (the loop then goes round the hole instead).
std::vector<std::vector<int>> loopsAroundHandles(const Segmentation& segmentation, int segment, double minLength = 0,
                                                 int roots = 8);

// A path through the inside of `segment` (on Segmentation::mesh) from the loop vertex nearest `near` [mesh units] to
// another loop vertex, across the segment: the shortest whose ends lie at least twice its length apart along the loop
// (a shorter way round would only cut a corner off). A band that would overlap itself when laid flat, cut across where
// its outline crosses itself, lies flat as two panels. Cut-mesh vertices from the start; empty where there is none.
std::vector<int> cutAcross(const Segmentation& segmentation, int segment, const Eigen::Vector3d& near);

// A segment's spread (on Segmentation::mesh): the area-weighted centre of its triangles and its principal axes, the
// least spread first (the columns of `axes`); area 0 when it has none.
struct SegmentSpread {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  double area = 0;
};
SegmentSpread segmentSpread(const Segmentation& segmentation, int segment);

// A path through the inside of `segment` (on Segmentation::mesh), a disk, that halves it along its length: from a
// vertex of its loop through its tip (the inside vertex farthest from the loop) to a loop vertex on the other side, as
// a pattern maker halves a tail or a trunk into two mirror pieces sewn along it. It keeps to where the surface is seen
// edge-on from the segment's flattest direction (the inner and the outer side of a curled tail). Where the ways down
// from the tip share their first edges, the path turns where they part. Cut-mesh vertices from one loop vertex to the
// other; empty where the segment has no inside vertex or is not one loop, or where a piece would still be too big for
// its seam (a flat panel inside it covering less than `minFlatShare` of it, as SegmentationOptions measures: a part
// over several limbs, which a section across each opens instead).
std::vector<int> cutAlong(const Segmentation& segmentation, int segment, double minFlatShare);

}  // namespace billow
