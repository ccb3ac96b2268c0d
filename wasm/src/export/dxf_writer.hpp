// DXF R12 (AC1009) ASCII, the dialect every cutter and CAM program opens: HEADER ($ACADVER, $INSUNITS = 4
// millimetres, extents), TABLES (LTYPE CONTINUOUS; LAYER CUT, SEW, NOTCH, LABEL with colors), an empty
// BLOCKS section, ENTITIES (closed POLYLINE/VERTEX/SEQEND for outlines, LINE for notches, TEXT for labels).
#pragma once
#include <string>

#include "export/drawing.hpp"

namespace billow {

std::string writeDxf(const Drawing& drawing);

const char* dxfLayerName(Layer layer);  // "CUT", "SEW", "NOTCH", "LABEL"

// TEXT value escaping for R12: % becomes %%% (a literal percent), non-ASCII becomes \U+XXXX, control
// characters are dropped (a group value must stay on one line).
std::string escapeDxfText(const std::string& utf8);

}  // namespace billow
