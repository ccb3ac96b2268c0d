// SVG at true scale: the document is `width`mm x `length`mm with a viewBox in millimetres, one group
// (an Inkscape layer) per drawing layer: cut, sew, notches, labels. y is flipped (SVG y runs down) so that
// pieces are not mirrored.
#pragma once
#include <string>

#include "export/drawing.hpp"

namespace billow {

std::string writeSvg(const Drawing& drawing, const std::string& title);

// XML text/attribute escaping: & < > " ' become entities, control characters are dropped.
std::string escapeXml(const std::string& text);

}  // namespace billow
