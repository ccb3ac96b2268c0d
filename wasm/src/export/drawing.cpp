#include "export/drawing.hpp"

namespace billow {

const char* layerName(Layer layer) {
  switch (layer) {
    case Layer::Seal:
      return "seal-band";
    case Layer::Valve:
      return "valves";
    case Layer::Cut:
      return "cut";
    case Layer::Sew:
      return "sew";
    case Layer::Notch:
      return "notches";
    case Layer::Label:
      return "labels";
  }
  return "";
}

// Cut black (what the blade or laser follows), sewing line blue, notches red, labels grey; the seal band's
// sealing line amber (its band a light tint of it, svg/pdf writers), valve gaps green.
const char* layerColor(Layer layer) {
  switch (layer) {
    case Layer::Seal:
      return "#b8860b";
    case Layer::Valve:
      return "#1a9850";
    case Layer::Cut:
      return "#000000";
    case Layer::Sew:
      return "#1f5fbf";
    case Layer::Notch:
      return "#d62728";
    case Layer::Label:
      return "#555555";
  }
  return "#000000";
}

int layerAciColor(Layer layer) {
  switch (layer) {
    case Layer::Seal:
      return 2;  // yellow
    case Layer::Valve:
      return 3;  // green
    case Layer::Cut:
      return 7;  // white/black
    case Layer::Sew:
      return 5;  // blue
    case Layer::Notch:
      return 1;  // red
    case Layer::Label:
      return 8;  // grey
  }
  return 7;
}

}  // namespace billow
