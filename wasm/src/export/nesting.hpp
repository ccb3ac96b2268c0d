// Nesting: lays the cut pieces out on a sheet (a roll) of a given width without overlap.
// Sheet frame: x across the roll in [0, width], y along it from 0 (the roll's start); units of the input.
// Each piece tries a few rotations (0/90/180/270 degrees and its principal axis along or across the roll),
// then goes where its bounding box sits lowest on a skyline of the pieces placed so far (bottom-left rule);
// pieces are taken largest first. Bounding boxes never overlap, so pieces never do.
#pragma once
#include <vector>

#include "export/polygon.hpp"

namespace billow {

struct NestOptions {
  double sheetWidth = 1000;  // across the roll
  double gap = 3;            // between pieces' bounding boxes, and from the sheet edges
  bool allowRotation = true;
  // Keep each piece's grain: its pattern y axis stays along the roll (only 0 and 180 degrees).
  bool grainLock = false;
};

struct NestResult {
  std::vector<Placement2> placements;  // one per piece: sheet point = placement.apply(piece point)
  double length = 0;                   // sheet length used (including the gap after the last piece)
  double utilisation = 0;              // piece area / (width x length)
};

// Throws billow::Error("export.sheet-too-narrow") naming the piece that fits in no orientation (its message
// assumes millimetres), with the sheet width that fits every piece (Error::sheetWidth).
NestResult nestPieces(const std::vector<Polygon2>& pieces, const NestOptions& options,
                      const std::vector<std::string>& names = {});

// Angle (radians) of a polygon's principal axis (the major axis of its area's second moment).
double principalAxisAngle(const Polygon2& p);

}  // namespace billow
