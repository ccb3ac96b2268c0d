// billow suggest DESIGN_OR_MESH --panels N --out-dir DIR [--symmetry] [--keep-seams] [--cut-thin-handles]
//                [--close-holes] [--height M] [--up AXIS] [--resolution TRIANGLES] [--max-iterations N] [--optimize K]
//                [--quiet]: seam layouts for a target nobody has patterned yet (suggest/seam_layouts.hpp), each given a
// first look (its flattened panels inflated), the K most promising (lookPromise) optimized at a coarse resolution and
// ranked by how close their optimized panels inflate to the target.
// Writes DIR/layout-K.billow.json (the design, best first), DIR/layout-K.pattern.json (its optimized coarse panels) and
// DIR/summary.json.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "io/mesh_file.hpp"
#include "io/pattern_json.hpp"
#include "suggest/seam_layouts.hpp"
#include "suggest/thin_handles.hpp"
#include "util/error.hpp"

namespace billow::cli {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f %%", 100 * share);
  return text;
}

int suggestUsage(bool help) {
  std::fprintf(help ? stdout : stderr,
               "usage: billow suggest DESIGN_OR_MESH --panels N --out-dir DIR [--symmetry] [--keep-seams]\n"
               "                      [--cut-thin-handles] [--close-holes] [--height METERS] [--up AXIS]\n"
               "                      [--resolution TRIANGLES]\n"
               "                      [--max-iterations N] [--optimize K] [--quiet]\n\n"
               "Suggests seam layouts for a target shape (a design file, or a mesh file made into a design of\n"
               "--height meters, default 0.6, along --up: +y, +z, ...; a mesh that stands only on its Z bottom,\n"
               "as CAD and 3D-printing files are made, is taken Z up, as the app does): layouts of plane\n"
               "sections, outlines, seams around limbs and along creases with at most N panels (2 to 40), seams\n"
               "added where a section leaves a part that is not a panel (a tube around a limb). Each is first\n"
               "inflated flat; the K that leave least of the target's surface away from the balloon (default 8)\n"
               "are optimized at a coarse resolution (default 1000 triangles, at most 40 iterations, fewer where\n"
               "the balloon keeps settling, as a limb swinging slowly on wrinkled fabric does) and ranked by their\n"
               "distance to the target (the worse way).\n"
               "--symmetry keeps the target's mirror symmetry (the design's symmetry plane, else the one the\n"
               "shape has); --keep-seams adds to the design's own seams.\n"
               "--cut-thin-handles cuts through the handles too thin for a panel to follow (a boot's lace loops:\n"
               "loops around them shorter than a tenth of the shape's size) and closes their ends, as the app's\n"
               "\"Cut the thin handles\" does; --close-holes closes an open mesh's holes (a statue open at its\n"
               "base) with caps, as the app's \"Close the holes\" does. The layouts' designs say so.\n"
               "Writes DIR/layout-K.billow.json (best first), DIR/layout-K.pattern.json and DIR/summary.json.\n"
               "Exit code 0 when some layout could be made into panels, 1 when none could.\n");
  return help ? 0 : 2;
}

bool isDesignFile(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  return ext == ".json";
}

// The design the layouts are laid on, and the path its relative target is read from. guessUp: a mesh file without --up,
// whose up axis its check guesses (loadDesignTargetScene).
Design readInput(const std::string& path, const Args& args, std::string& designPath, bool& guessUp) {
  guessUp = false;
  if (isDesignFile(path)) {
    designPath = path;
    return readDesignJson(readFileBytes(path));
  }
  Design design;
  design.target.kind = DesignTarget::Obj;
  design.target.name = fs::absolute(path).lexically_normal().string();
  design.height = numberOption(args, "--height", 0.6, "a height in meters");
  if (!(design.height > 0)) throw Error("cli.usage", "the option --height needs a positive height in meters");
  guessUp = !args.has("--up");
  if (!guessUp && !parseUpAxis(args.get("--up"), design.target.up))
    throw Error("cli.usage", "the option --up needs +y, -y, +z, -z, +x or -x, not '" + args.get("--up") + "'");
  designPath = (fs::current_path() / "design.billow.json").string();
  return design;
}

// The design as written into DIR: a mesh file named relative to DIR.
Design forOutDir(Design design, const std::string& designPath, const std::string& dir) {
  if (design.target.kind == DesignTarget::Obj || design.target.kind == DesignTarget::File) {
    fs::path mesh = design.target.name;
    if (mesh.is_relative()) mesh = fs::absolute(designPath).parent_path() / mesh;
    design.target.name = fs::relative(mesh, fs::absolute(dir)).string();
  }
  return design;
}

}  // namespace

int suggestCommand(const std::vector<std::string>& argv) {
  const Args args =
      parseArgs(argv, {"--panels", "--out-dir", "--height", "--up", "--resolution", "--max-iterations", "--optimize"});
  if (args.has("--help") || args.positional.size() != 1 || !args.has("--out-dir") || !args.has("--panels"))
    return suggestUsage(args.has("--help"));
  const bool quiet = args.has("--quiet");
  const std::string dir = args.get("--out-dir");
  LayoutRequest request;
  request.panels = intOption(args, "--panels", 6, 2, 40, "a panel count");
  EvaluateOptions evaluate;
  evaluate.triangles = intOption(args, "--resolution", evaluate.triangles, 200, 20000, "a triangle count");
  evaluate.maxIterations = intOption(args, "--max-iterations", evaluate.maxIterations, 1, 300, "an iteration count");
  const int optimized = intOption(args, "--optimize", kOptimizedLayouts, 1, 100, "a number of layouts");

  std::string designPath;
  bool guessUp = false;
  Design read = readInput(args.positional[0], args, designPath, guessUp);
  if (args.has("--cut-thin-handles")) read.target.cutThinHandles = true;
  if (args.has("--close-holes")) read.target.closeHoles = true;
  const std::unique_ptr<DesignScene> scene =
      loadDesignTargetScene(read, designPath, exampleSearchPath(executableDir()), guessUp);
  const Design input = scene->design;  // as read, its up axis guessed: the layouts change the scene's own
  if (guessUp && input.target.up.axis == 2 && !quiet)
    std::fprintf(stderr,
                 "%s looks made Z up, as files from CAD and 3D printing often are: it stands on its Z bottom and "
                 "would tip over on its Y bottom, so its height is measured along Z (--up +y keeps Y up)\n",
                 args.positional[0].c_str());
  evaluate.cut = designFabrication(input);  // the sheet and allowance its pieces are nested with
  request.up = input.target.up;
  if (args.has("--symmetry")) {
    request.symmetryAxis = designSymmetryAxis(input);
    if (request.symmetryAxis < 0) request.symmetryAxis = mirrorSymmetryAxis(scene->target, *scene->projector);
    if (request.symmetryAxis < 0)
      throw Error("suggest.no-symmetry",
                  "this shape is not its own mirror image across the middle of its box along x, y or z, so no layout "
                  "can keep a symmetry it does not have: leave out --symmetry");
  }
  // A fine target's layouts are laid on a simplified copy of it, the designer's seams carried there, and theirs back.
  Design scaled = scene->design;
  scaled.scale = scene->scale;
  TriMesh ownUnits = scene->target;
  ownUnits.V /= scene->scale;
  const std::unique_ptr<DesignScene> copy = suggestionScene(scaled, ownUnits);
  DesignScene& laid = copy ? *copy : *scene;
  const std::vector<DesignSeam> kept = !args.has("--keep-seams") ? std::vector<DesignSeam>{}
                                       : copy                    ? carriedSeams(input.seams, *scene, *copy)
                                                                 : input.seams;
  if (copy && !quiet)
    std::fprintf(stderr, "%s: %d triangles, the layouts laid on a copy of %d\n", args.positional[0].c_str(),
                 scene->target.numTriangles(), copy->target.numTriangles());
  const std::vector<LayoutProposal> proposals = proposeLayouts(laid.target, request);
  if (!quiet)
    std::fprintf(stderr, "%s: %zu layouts of at most %d panels to try%s\n", args.positional[0].c_str(),
                 proposals.size(), request.panels,
                 request.symmetryAxis >= 0
                     ? (", mirror-symmetric across " + std::string(1, "xyz"[request.symmetryAxis])).c_str()
                     : "");

  // A first look at every layout (its segments opened into panels, the flattened panels inflated), then the most
  // promising few optimized.
  struct Tried {
    const LayoutProposal* proposal = nullptr;
    LayoutEvaluation first, result;
  };
  std::vector<Tried> tried;
  std::vector<std::vector<DesignSeam>> lookedSeams;
  for (size_t i = 0; i < proposals.size(); ++i) {
    Tried t;
    t.proposal = &proposals[i];
    t.first = lookAtLayout(laid, proposals[i], kept, request.panels, lookedSeams, evaluate);
    if (t.first.ok) lookedSeams.push_back(t.first.seams);
    if (!quiet)
      std::fprintf(
          stderr, "  look %2zu/%zu  %-58s %s\n", i + 1, proposals.size(), proposals[i].name.c_str(),
          t.first.ok ? (std::to_string(t.first.panels) + " panels, first look " + percent(lookPromise(t.first))).c_str()
                     : ("not used: " + t.first.problem).c_str());
    tried.push_back(std::move(t));
  }
  std::vector<const LayoutEvaluation*> looks;
  std::vector<std::string> families;
  for (const Tried& t : tried) looks.push_back(&t.first), families.push_back(layoutFamily(*t.proposal));
  std::vector<Tried*> looked;
  for (int i : looksToOptimize(looks, families, optimized)) looked.push_back(&tried[i]);
  for (size_t i = 0; i < looked.size(); ++i) {
    Tried& t = *looked[i];
    t.result = evaluateLayout(laid, t.first.seams, int(t.first.seams.size()), evaluate, t.first.connections);
    if (!quiet) {
      if (t.result.ok)
        std::fprintf(stderr, "  optimize %zu/%zu  %-54s %2d panels, seams %.2f m, distance %.2f %% (%.1f s)\n", i + 1,
                     looked.size(), t.proposal->name.c_str(), t.result.panels, t.result.seamLength,
                     100 * t.result.distance, t.result.ms / 1000);
      else
        std::fprintf(stderr, "  optimize %zu/%zu  %-54s not used: %s\n", i + 1, looked.size(), t.proposal->name.c_str(),
                     t.result.problem.c_str());
    }
  }
  // Best first: those that fit the sheet, then the closest.
  std::vector<const LayoutEvaluation*> results;
  for (const Tried* t : looked) results.push_back(&t->result);
  std::vector<const Tried*> ranked;
  for (int i : layoutsRanked(results)) ranked.push_back(looked[size_t(i)]);

  fs::create_directories(dir);
  json layouts = json::array(), notUsed = json::array();
  for (size_t r = 0; r < ranked.size(); ++r) {
    const Tried& t = *ranked[r];
    Design design = forOutDir(input, designPath, dir);
    if (kept.empty()) {  // the design's own seams, their fields and the internal connections between them go
      design.extra.erase("seams");
      design.connections.clear();
    }
    design.seams =
        copy ? carriedSeams(t.result.seams, *copy, *scene, kept.empty() ? kept : input.seams) : t.result.seams;
    addedFacePointsAsPositions(*scene, design.seams);
    design.connections.insert(design.connections.end(), t.result.connections.begin(), t.result.connections.end());
    if (request.symmetryAxis >= 0) design.extra["symmetry"] = {{"axis", std::string(1, "xyz"[request.symmetryAxis])}};
    const std::string stem = "layout-" + std::to_string(r + 1);
    writeFile(dir + "/" + stem + ".billow.json", writeDesignJson(design) + "\n");
    writeFile(dir + "/" + stem + ".pattern.json", writePatternJson(t.result.pattern) + "\n");
    layouts.push_back({{"rank", r + 1},
                       {"name", t.proposal->name},
                       {"description", t.first.description()},
                       {"design", stem + ".billow.json"},
                       {"pattern", stem + ".pattern.json"},
                       {"panels", t.result.panels},
                       {"seam_length_m", t.result.seamLength},
                       {"sheet_use", t.result.sheetUse},
                       {"sheet_needed_mm", t.result.sheetNeeded},
                       {"distance",
                        {{"worse_way_rms", t.result.distance},
                         {"inflated_to_target_rms", t.result.inflatedToTarget},
                         {"target_to_inflated_rms", t.result.targetToInflated}}},
                       // What chose it for optimizing (looksToOptimize), so a bench can replay the choice.
                       {"first_look",
                        {{"worse_way_rms", t.first.distance},
                         {"target_to_inflated_rms", t.first.targetToInflated},
                         {"promise", lookPromise(t.first)},
                         {"rank", lookRank(t.first)},
                         {"family", layoutFamily(*t.proposal)}}},
                       {"iterations", t.result.iterations},
                       {"ms", t.result.ms}});
  }
  for (const Tried& t : tried)
    if (!t.first.ok) notUsed.push_back({{"name", t.proposal->name}, {"why", t.first.problem}});
  const json summary = {
      {"format", "billow-suggest"},
      {"version", 1},
      {"target", args.positional[0]},
      {"panels", request.panels},
      {"symmetry", request.symmetryAxis >= 0 ? json(std::string(1, "xyz"[request.symmetryAxis])) : json(nullptr)},
      {"resolution", evaluate.triangles},
      {"optimized",
       {{"layouts", optimized}, {"by_default", kOptimizedLayouts}, {"of_one_family", kOptimizedOfOneFamily}}},
      {"layouts", layouts},
      {"not_used", notUsed}};
  writeFile(dir + "/summary.json", summary.dump(2) + "\n");
  std::printf("rank  panels  distance %%  seams m  layout\n");
  for (const json& l : layouts) {
    // A layout with a piece wider than the sheet comes after those that fit, whatever its distance: say why.
    const double sheet = l["sheet_needed_mm"].get<double>();
    const std::string needs = sheet > 0 ? " (needs a " + std::to_string(std::lround(sheet)) + " mm sheet)" : "";
    std::printf("%4d  %6d  %10.2f  %7.2f  %s%s\n", l["rank"].get<int>(), l["panels"].get<int>(),
                100 * l["distance"]["worse_way_rms"].get<double>(), l["seam_length_m"].get<double>(),
                l["name"].get<std::string>().c_str(), needs.c_str());
  }
  if (ranked.empty()) {
    // Each handle needs a seam around it, and a thin one cannot have a panel round it: more panels will not help.
    const size_t thin = input.target.cutThinHandles ? 0 : thinHandles(laid.target).size();
    const std::string why = thin ? "; the shape has " + std::to_string(thin) + " thin handle" + (thin > 1 ? "s" : "") +
                                       " no panel can follow: --cut-thin-handles cuts through " +
                                       (thin > 1 ? "them" : "it")
                                 : "; try more panels";
    std::fprintf(stderr,
                 "billow suggest: none of the %zu layouts could be made into at most %d panels on this shape (why: "
                 "%s/summary.json)%s\n",
                 proposals.size(), request.panels, dir.c_str(), why.c_str());
    return 1;
  }
  return 0;
}

}  // namespace billow::cli
