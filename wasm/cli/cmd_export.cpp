// billow export PATTERN.json --out-dir DIR [--allowance MM] [--seam-allowance SEAM=MM ...]
//                            [--free-edge-allowance MM] [--sheet-width MM] [--paper a4|letter]
//                            [--notch-spacing MM] [--overlap MM] [--units mm|in] [--grain-lock] [--no-rotate]
//                            [--sealed] [--valve SEAM=MM[@AT] ...]
// Writes DIR/pattern.svg, DIR/pattern.dxf, DIR/pattern.pdf and DIR/stats.json.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>

#include "cli/commands.hpp"
#include "export/export.hpp"
#include "io/pattern_json.hpp"
#include "util/error.hpp"

namespace billow::cli {

namespace {

double millimetres(const Args& args, const std::string& name, double fallback) {
  return numberOption(args, name, fallback, "a length in mm");
}

// A number that is the whole of `text`.
bool wholeNumber(const std::string& text, double& out) {
  try {
    size_t used = 0;
    out = std::stod(text, &used);
    return used == text.size();
  } catch (const std::exception&) {
    return false;
  }
}

// --valve SEAM=MM[@AT]: a fill valve MM wide on seam SEAM (S4 or 3), centred at AT of its length (0.5).
FillValve valveOption(const std::string& value) {
  const auto fail = [&](const std::string& why) -> FillValve {
    throw Error("cli.usage", "the option --valve needs SEAM=MM or SEAM=MM@AT, like S1=20 or S1=20@0.25 (" + why +
                                 "), not '" + value + "'");
  };
  const size_t eq = value.find('='), at = value.find('@');
  if (eq == std::string::npos) return fail("no '='");
  std::string seam = value.substr(0, eq);
  const bool label = !seam.empty() && (seam[0] == 'S' || seam[0] == 's');
  if (label) seam.erase(0, 1);
  if (seam.empty() || seam.size() > 6 || seam.find_first_not_of("0123456789") != std::string::npos ||
      std::stoi(seam) - (label ? 1 : 0) < 0)
    return fail("the seam is its label S1, S2, ... or its id 0, 1, ...");
  FillValve valve;
  valve.seam = std::stoi(seam) - (label ? 1 : 0);
  if (!wholeNumber(value.substr(eq + 1, at == std::string::npos ? std::string::npos : at - eq - 1), valve.width) ||
      !(valve.width > 0))
    return fail("the width is a length in mm");
  if (at != std::string::npos && (!wholeNumber(value.substr(at + 1), valve.at) || !(valve.at >= 0 && valve.at <= 1)))
    return fail("AT is a share of the seam's length, from 0 to 1");
  return valve;
}

// --seam-allowance SEAM=MM: SEAM is the seam's label on the pieces (S4) or its id in stats.json (3).
std::pair<int, double> seamAllowanceOption(const std::string& value) {
  const auto fail = [&](const std::string& why) -> std::pair<int, double> {
    throw Error("cli.usage",
                "the option --seam-allowance needs SEAM=MM, like S4=0 or 3=15 (" + why + "), not '" + value + "'");
  };
  const size_t eq = value.find('=');
  if (eq == std::string::npos) return fail("no '='");
  std::string seam = value.substr(0, eq);
  const bool label = !seam.empty() && (seam[0] == 'S' || seam[0] == 's');
  if (label) seam.erase(0, 1);
  if (seam.empty() || seam.size() > 6 || seam.find_first_not_of("0123456789") != std::string::npos)
    return fail("the seam is its label S1, S2, ... or its id 0, 1, ...");
  const int id = std::stoi(seam) - (label ? 1 : 0);
  if (id < 0) return fail("the labels start at S1");
  const std::string mm = value.substr(eq + 1);
  try {
    size_t used = 0;
    const double width = std::stod(mm, &used);
    if (used == mm.size()) return {id, width};
  } catch (const std::exception&) {
  }
  return fail("the width is a length in mm");
}

}  // namespace

int exportCommand(const std::vector<std::string>& argv) {
  const Args args = parseArgs(argv, {"--out-dir", "--allowance", "--seam-allowance", "--free-edge-allowance",
                                     "--sheet-width", "--paper", "--notch-spacing", "--overlap", "--units", "--valve"});
  if (args.has("--help") || args.positional.size() != 1 || !args.has("--out-dir")) {
    std::fprintf(
        args.has("--help") ? stdout : stderr,
        "usage: billow export PATTERN.json --out-dir DIR [--allowance MM] [--seam-allowance SEAM=MM ...]\n"
        "                     [--free-edge-allowance MM] [--sheet-width MM] [--paper a4|letter]\n"
        "                     [--notch-spacing MM] [--overlap MM] [--units mm|in] [--grain-lock] [--no-rotate]\n"
        "                     [--sealed] [--valve SEAM=MM[@AT] ...]\n\n"
        "Writes the cut files DIR/pattern.svg and DIR/pattern.dxf (the pieces nested on a sheet), a\n"
        "printable DIR/pattern.pdf (overview, then true-scale tiles) and DIR/stats.json.\n"
        "  --allowance MM             seam allowance of every seam (0 for heat sealing)\n"
        "  --seam-allowance SEAM=MM   one seam's own allowance; SEAM is its label on the pieces (S4) or\n"
        "                             its id in stats.json (3); repeat for more seams\n"
        "  --free-edge-allowance MM   allowance of edges sewn to nothing (openings, hems)\n"
        "  --grain-lock               keep each panel's y axis along the roll (turned 0 or 180 degrees)\n"
        "  --no-rotate                nest the panels as drawn (not turned)\n"
        "  --sealed                   heat sealed (foil): the allowance is the seal band, drawn as a band\n"
        "  --valve SEAM=MM[@AT]       a fill valve: MM left open on seam SEAM on both pieces, centred at\n"
        "                             AT of the seam's length (0 to 1, default 0.5); repeat for more\n"
        "Defaults: 10 mm seam allowance, free edges as the seams, 1000 mm sheet, A4, notches every\n"
        "100 mm, 10 mm tile overlap, panels turned as they nest best.\n");
    return args.has("--help") ? 0 : 2;
  }
  ExportOptions o;
  o.allowance = millimetres(args, "--allowance", o.allowance);
  o.freeEdgeAllowance = millimetres(args, "--free-edge-allowance", o.freeEdgeAllowance);
  if (args.has("--free-edge-allowance") && o.freeEdgeAllowance < 0)
    throw Error("cli.usage", "the option --free-edge-allowance needs a length of 0 mm or more");
  for (const auto& [name, value] : args.options) {
    if (name != "--seam-allowance") continue;
    const auto seam = seamAllowanceOption(value);
    for (const auto& given : o.seamAllowance)
      if (given.first == seam.first)
        throw Error("cli.usage",
                    "the seam S" + std::to_string(seam.first + 1) + " is given two allowances (--seam-allowance)");
    o.seamAllowance.push_back(seam);
  }
  o.sheetWidth = millimetres(args, "--sheet-width", o.sheetWidth);
  o.notchSpacing = millimetres(args, "--notch-spacing", o.notchSpacing);
  o.tileOverlap = millimetres(args, "--overlap", o.tileOverlap);
  const std::string paper = args.get("--paper", "a4");
  if (paper != "a4" && paper != "letter") throw Error("cli.usage", "--paper is a4 or letter, not '" + paper + "'");
  o.paper = paper == "a4" ? PaperSize::A4 : PaperSize::Letter;
  const std::string units = args.get("--units", "mm");
  if (units != "mm" && units != "in") throw Error("cli.usage", "--units is mm or in, not '" + units + "'");
  o.units = units == "mm" ? DisplayUnits::Millimeters : DisplayUnits::Inches;
  o.grainLock = args.has("--grain-lock");
  o.allowRotation = !args.has("--no-rotate");
  o.sealed = args.has("--sealed");
  for (const auto& [name, value] : args.options)
    if (name == "--valve") o.valves.push_back(valveOption(value));

  const std::string input = args.positional[0];
  std::ifstream in(input, std::ios::binary);
  if (!in) throw Error("io.cannot-read", "cannot read " + input);
  std::stringstream text;
  text << in.rdbuf();
  const Pattern pattern = readPatternJson(text.str());
  o.title = std::filesystem::path(input).stem().string();
  const ExportBundle bundle = exportPattern(pattern, o);

  const std::filesystem::path dir = args.get("--out-dir");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("io.cannot-write", "cannot create the folder " + dir.string() + ": " + ec.message());
  writeFile((dir / "pattern.svg").string(), bundle.svg);
  writeFile((dir / "pattern.dxf").string(), bundle.dxf);
  writeFile((dir / "pattern.pdf").string(), bundle.pdf);
  writeFile((dir / "stats.json").string(), bundle.statistics + "\n");
  const auto stats = nlohmann::json::parse(bundle.statistics)["totals"];
  std::printf("%s: %d panels on a %.0f x %.0f mm sheet (%.0f %% used), %d seams, %.0f mm of seams; wrote %s\n",
              input.c_str(), stats["panels"].get<int>(), o.sheetWidth, stats["sheet_length_mm"].get<double>(),
              100 * stats["utilisation"].get<double>(), stats["seams"].get<int>(),
              stats["seam_length_mm"].get<double>(), dir.string().c_str());
  return 0;
}

}  // namespace billow::cli
