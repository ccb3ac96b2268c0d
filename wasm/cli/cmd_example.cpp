// billow example NAME [--triangles N] [--size M] [--aspect R] [--pressure PA] [--material NAME] --out FILE.json
#include <cstdio>
#include <fstream>

#include "cli/commands.hpp"
#include "io/pattern_json.hpp"
#include "simulate/example_patterns.hpp"
#include "util/error.hpp"

namespace billow::cli {

int exampleCommand(const std::vector<std::string>& argv) {
  const Args args = parseArgs(argv, {"--triangles", "--size", "--aspect", "--pressure", "--material", "--out"});
  if (args.has("--help") || args.positional.size() != 1 || !args.has("--out")) {
    std::fprintf(
        args.has("--help") ? stdout : stderr,
        "usage: billow example NAME [--triangles N] [--size M] [--aspect R] [--pressure PA] [--material NAME]\n"
        "                      --out FILE.json\n\n"
        "Writes an example pattern. Flat-sewn: mylar (two discs of radius M), pillow (two rectangles M wide\n"
        "and R x M long, squares by default), gusset-pillow (the same joined by a strip M/4 wide), ring (two\n"
        "rings of outer radius M), letter-L, letter-C, star, heart (two pieces M high), cube (six squares of\n"
        "side M). Gored: sphere3 (three gores of a sphere of radius M), sphere3-internal (plus an internal\n"
        "panel).\n"
        "Defaults: 3000 triangles, 0.3 m, 1000 Pa, "
        "foil 25 um, E = 3 GPa. Materials: foil, pvc, ripstop, tpu.\n");
    return args.has("--help") ? 0 : 2;
  }
  ExampleOptions o;
  o.triangles = static_cast<int>(numberOption(args, "--triangles", o.triangles));
  o.size = numberOption(args, "--size", o.size);
  o.aspect = numberOption(args, "--aspect", o.aspect);
  o.pressure = numberOption(args, "--pressure", o.pressure);
  o.material = materialOption(args, o.material);
  const Pattern p = examplePattern(args.positional[0], o);
  const std::string out = args.get("--out");
  std::ofstream file(out, std::ios::binary);
  file << writePatternJson(p) << "\n";
  if (!file) throw Error("io.cannot-write", "cannot write " + out);
  long long triangles = 0;
  for (const Panel& panel : p.panels) triangles += panel.triangles.rows();
  std::printf("%s: %zu panels, %lld triangles, %zu stitches\n", out.c_str(), p.panels.size(), triangles,
              p.stitches.size());
  return 0;
}

}  // namespace billow::cli
