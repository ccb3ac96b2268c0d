#include "export/drawing.hpp"

namespace billow {

const char* layerName(Layer layer) {
  switch (layer) {
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

// Cut black (what the blade or laser follows), sewing line blue, notches red, labels grey.
const char* layerColor(Layer layer) {
  switch (layer) {
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
