// The laid-out sheet as plain vector geometry, shared by the SVG, DXF and PDF writers.
// Sheet frame in millimetres, y up: x across the sheet in [0, width], y along it in [0, length].
#pragma once
#include <string>
#include <vector>

#include "export/polygon.hpp"

namespace billow {

// Seal: a heat-sealed panel's seal band, between its sealing line and its cut line (drawn under the lines;
// it replaces Sew). Valve: the gaps left in the seal or seam for fill valves, over the band and under the
// cut line. Both only when present.
enum class Layer { Seal, Valve, Cut, Sew, Notch, Label };
constexpr Layer kLayers[] = {Layer::Seal, Layer::Valve, Layer::Cut, Layer::Sew, Layer::Notch, Layer::Label};

const char* layerName(Layer layer);           // "seal-band", "valves", "cut", "sew", "notches", "labels"
const char* layerColor(Layer layer);          // "#rrggbb" as drawn in SVG and PDF
int layerAciColor(Layer layer);               // AutoCAD color index for DXF
constexpr const char* kSealTint = "#f6e7bd";  // the seal band's fill: a light tint of the Seal layer's amber

struct DrawnPath {
  Layer layer = Layer::Cut;
  int panel = -1;
  bool closed = false;
  Polygon2 points;  // [mm]
  Polygon2 band;    // Seal: the band's outer edge (the cut line); `points` is its inner edge, the sealing line
};

struct DrawnText {
  Layer layer = Layer::Label;
  int panel = -1;
  Vec2 at{0, 0};      // centre of the text's baseline [mm]
  double height = 5;  // font size (em) [mm]
  std::string text;   // UTF-8, any characters (writers escape)
};

struct Drawing {
  double width = 0, length = 0;  // [mm]
  std::vector<DrawnPath> paths;
  std::vector<DrawnText> texts;
};

}  // namespace billow
