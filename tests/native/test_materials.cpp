// Material presets: every preset is physically sensible, the default Material is the foil preset, and a
// design naming a preset gets its figures (fields given beside the name override them).
#include <gtest/gtest.h>

#include "io/design_json.hpp"
#include "simulate/materials.hpp"

namespace billow {
namespace {

TEST(Materials, PresetsAreSensibleAndFoilIsTheDefault) {
  ASSERT_GE(materialPresets().size(), 3u);
  for (const MaterialPreset& p : materialPresets()) {
    EXPECT_GT(p.material.thickness, 1e-6) << p.material.name;
    EXPECT_LT(p.material.thickness, 2e-3) << p.material.name;
    EXPECT_GT(p.material.youngsModulus, 1e6) << p.material.name;
    EXPECT_LT(p.material.youngsModulus, 1e10) << p.material.name;
    EXPECT_GT(p.material.density, 100) << p.material.name;
    EXPECT_GT(p.strength, 1e6) << p.material.name;
    EXPECT_FALSE(p.label.empty());
    EXPECT_EQ(findMaterialPreset(p.material.name), &p);
  }
  const Material foil;
  ASSERT_NE(findMaterialPreset("foil"), nullptr);
  EXPECT_EQ(findMaterialPreset("foil")->material.thickness, foil.thickness);
  EXPECT_EQ(findMaterialPreset("foil")->material.youngsModulus, foil.youngsModulus);
  EXPECT_EQ(findMaterialPreset("kevlar"), nullptr);
  ASSERT_NE(findMaterialPreset("pvc"), nullptr);
  EXPECT_EQ(findMaterialPreset("pvc")->material.thickness, 0.3e-3);
}

TEST(Materials, DesignNamingAPresetGetsItsFigures) {
  const std::string base = R"({"format":"billow-design","version":1,"target":{"example":"sphere"},"seams":[],)";
  const Design pvc = readDesignJson(base + R"("material":{"name":"pvc"}})");
  EXPECT_EQ(pvc.material.name, "pvc");
  EXPECT_EQ(pvc.material.thickness, findMaterialPreset("pvc")->material.thickness);
  EXPECT_EQ(pvc.material.youngsModulus, findMaterialPreset("pvc")->material.youngsModulus);
  const Design thicker = readDesignJson(base + R"("material":{"name":"pvc","thickness":0.0005}})");
  EXPECT_EQ(thicker.material.thickness, 0.0005);
  EXPECT_EQ(thicker.material.youngsModulus, findMaterialPreset("pvc")->material.youngsModulus);
  const Design custom = readDesignJson(base + R"("material":{"name":"mine","thickness":0.0001,"youngs_modulus":5e7}})");
  EXPECT_EQ(custom.material.name, "mine");
  EXPECT_EQ(custom.material.youngsModulus, 5e7);
}

}  // namespace
}  // namespace billow
