// Sheet materials a designer picks by name. The figures are typical values for an isotropic membrane
// model (the simulator knows no weave direction): a woven fabric's Young's modulus here is its effective
// in-plane stiffness (tension per unit strain) divided by the nominal thickness.
#pragma once
#include <string>
#include <vector>

#include "pattern/pattern.hpp"

namespace billow {

struct MaterialPreset {
  Material material;  // name, thickness [m], Young's modulus [Pa], density [kg/m^3]
  std::string label;  // what the designer reads: "Foil (metallized nylon, 25 µm)"
  double strength;    // [Pa] where the sheet tears or its seal gives way; safe in use at half of it
};

// foil, pvc, ripstop, tpu; the first is the default (Material{}'s values).
const std::vector<MaterialPreset>& materialPresets();

// nullptr when no preset has this name.
const MaterialPreset* findMaterialPreset(const std::string& name);

// The material called `name`: a preset's figures when there is one, else `base` under that name. Readers
// then let the figures given beside the name override it.
Material namedMaterial(const std::string& name, Material base);

// What readers accept for a sheet: thickness [m] and Young's modulus [Pa].
constexpr double kMinThickness = 1e-7, kMaxThickness = 0.01;
constexpr double kMinYoungsModulus = 1e3, kMaxYoungsModulus = 1e13;

}  // namespace billow
