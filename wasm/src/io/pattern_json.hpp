// The pattern file (public format), read and written:
//   { "format": "billow-pattern", "version": 1, "units": "m", "pressure": 1000.0,
//     "material": { "name": "foil", "thickness": 2.5e-5, "youngs_modulus": 3.0e9, "density": 1390 },
//     "panels": [ { "name": "front", "internal": false, "vertices": [[x, y], ...], "triangles": [[i, j, k], ...] } ],
//     "stitches": [[panelA, vertexA, panelB, vertexB], ...],
//     "inflated": [ [[x, y, z], ...] per panel ] }
// Pressure in Pa, thickness in m, Young's modulus in Pa, density in kg/m^3 (optional). "units" is "m", "cm"
// or "mm" and scales panel vertices and "inflated" (not the thickness). Panel triangles are counterclockwise
// as seen from outside. "inflated" (optional) gives a 3D start position per panel vertex (stitched copies
// are averaged); without it the solver builds its own start. Unknown fields are ignored.
// Written files use "units": "m" and round-trip exactly.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "simulate/sewn_pattern.hpp"

namespace billow {

// Parses and validates (sews) the pattern. Throws billow::Error: pattern.json, pattern.unknown-format,
// pattern.version, pattern.bad-value, pattern.bad-index, pattern.too-large and the sewPattern codes.
// Sewing warnings (unequal seam lengths) go to `warnings` when given.
Pattern readPatternJson(std::string_view text, std::vector<PatternWarning>* warnings = nullptr,
                        const PatternLimits& limits = {});

std::string writePatternJson(const Pattern& pattern, int indent = -1);

}  // namespace billow
