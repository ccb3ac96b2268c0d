// The laid-out sheet as plain vector geometry, shared by the SVG, DXF and PDF writers.
// Sheet frame in millimetres, y up: x across the sheet in [0, width], y along it in [0, length].
#pragma once
#include <string>
#include <vector>

#include "export/polygon.hpp"

namespace billow {

enum class Layer { Cut, Sew, Notch, Label };
constexpr Layer kLayers[] = {Layer::Cut, Layer::Sew, Layer::Notch, Layer::Label};

const char* layerName(Layer layer);   // "cut", "sew", "notches", "labels"
const char* layerColor(Layer layer);  // "#rrggbb" as drawn in SVG and PDF
int layerAciColor(Layer layer);       // AutoCAD color index for DXF

struct DrawnPath {
  Layer layer = Layer::Cut;
  int panel = -1;
  bool closed = false;
  Polygon2 points;  // [mm]
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
