// Material presets (see materials.hpp). Sources for the orders of magnitude: BoPET/nylon film data sheets
// (E 2-4 GPa), plasticized PVC sheet for inflatables (E 10-40 MPa), silicone/PU-coated ripstop nylon
// (effective membrane stiffness ~100 kN/m), TPU film (E 10-50 MPa).
#include "simulate/materials.hpp"

namespace billow {
namespace {

MaterialPreset preset(const char* name, const char* label, double thickness, double youngs, double density,
                      double strength) {
  MaterialPreset p;
  p.material.name = name;
  p.material.thickness = thickness;
  p.material.youngsModulus = youngs;
  p.material.density = density;
  p.label = label;
  p.strength = strength;
  return p;
}

}  // namespace

const std::vector<MaterialPreset>& materialPresets() {
  static const std::vector<MaterialPreset> presets = {
      preset("foil", "Foil (metallized nylon, 25 \xC2\xB5m)", 25e-6, 3.0e9, 1150, 80e6),
      preset("pvc", "PVC sheet (0.3 mm)", 0.3e-3, 20e6, 1300, 16e6),
      preset("ripstop", "Coated ripstop nylon (0.1 mm)", 0.1e-3, 1.0e9, 700, 120e6),
      preset("tpu", "TPU film (0.2 mm)", 0.2e-3, 25e6, 1200, 30e6),
  };
  return presets;
}

const MaterialPreset* findMaterialPreset(const std::string& name) {
  for (const MaterialPreset& p : materialPresets())
    if (p.material.name == name) return &p;
  return nullptr;
}

Material namedMaterial(const std::string& name, Material base) {
  if (const MaterialPreset* preset = findMaterialPreset(name)) return preset->material;
  base.name = name;
  return base;
}

}  // namespace billow
