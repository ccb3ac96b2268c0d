// billow export PATTERN.json --out-dir DIR [--allowance MM] [--sheet-width MM] [--paper a4|letter]
//                            [--notch-spacing MM] [--overlap MM] [--units mm|in] [--grain-lock] [--no-rotate]
// Writes DIR/pattern.svg, DIR/pattern.dxf, DIR/pattern.pdf and DIR/stats.json.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.hpp"
#include "export/export.hpp"
#include "io/pattern_json.hpp"
#include "util/error.hpp"

namespace billow::cli {

namespace {

double millimetres(const Args& args, const std::string& name, double fallback) {
  return numberOption(args, name, fallback, "a length in mm");
}

void writeFile(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream file(path, std::ios::binary);
  file << bytes;
  if (!file) throw Error("io.cannot-write", "cannot write " + path.string());
}

}  // namespace

int exportCommand(const std::vector<std::string>& argv) {
  const Args args = parseArgs(
      argv, {"--out-dir", "--allowance", "--sheet-width", "--paper", "--notch-spacing", "--overlap", "--units"});
  if (args.has("--help") || args.positional.size() != 1 || !args.has("--out-dir")) {
    std::fprintf(args.has("--help") ? stdout : stderr,
                 "usage: billow export PATTERN.json --out-dir DIR [--allowance MM] [--sheet-width MM]\n"
                 "                     [--paper a4|letter] [--notch-spacing MM] [--overlap MM] [--units mm|in]\n"
                 "                     [--grain-lock] [--no-rotate]\n\n"
                 "Writes the cut files DIR/pattern.svg and DIR/pattern.dxf (the pieces nested on a sheet), a\n"
                 "printable DIR/pattern.pdf (overview, then true-scale tiles) and DIR/stats.json.\n"
                 "Defaults: 10 mm seam allowance (0 for heat sealing), 1000 mm sheet, A4, notches every 100 mm,\n"
                 "10 mm tile overlap.\n");
    return args.has("--help") ? 0 : 2;
  }
  ExportOptions o;
  o.allowance = millimetres(args, "--allowance", o.allowance);
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
  writeFile(dir / "pattern.svg", bundle.svg);
  writeFile(dir / "pattern.dxf", bundle.dxf);
  writeFile(dir / "pattern.pdf", bundle.pdf);
  writeFile(dir / "stats.json", bundle.statistics + "\n");
  const auto stats = nlohmann::json::parse(bundle.statistics)["totals"];
  std::printf("%s: %d panels on a %.0f x %.0f mm sheet (%.0f %% used), %d seams, %.0f mm of seams; wrote %s\n",
              input.c_str(), stats["panels"].get<int>(), o.sheetWidth, stats["sheet_length_mm"].get<double>(),
              100 * stats["utilisation"].get<double>(), stats["seams"].get<int>(),
              stats["seam_length_mm"].get<double>(), dir.string().c_str());
  return 0;
}

}  // namespace billow::cli
