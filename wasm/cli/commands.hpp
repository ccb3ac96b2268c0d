#pragma once
#include <string>
#include <vector>

#include "export/export_options.hpp"
#include "pattern/design_scene.hpp"
#include "pattern/pattern.hpp"

namespace billow::cli {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const std::vector<std::string>& args);  // exit code: 0 ok, 1 input rejected, 2 usage
};

const std::vector<Command>& commands();

// Shared argument helpers: `--name value` options and positional arguments.
struct Args {
  std::vector<std::string> positional;
  std::vector<std::pair<std::string, std::string>> options;  // "--out" -> "x.json"; flags map to ""
  bool has(const std::string& name) const;
  std::string get(const std::string& name, const std::string& fallback = "") const;
};
// flagsWithValue lists the options that take a value; anything else starting with -- is a flag.
Args parseArgs(const std::vector<std::string>& args, const std::vector<std::string>& flagsWithValue);
// --material NAME (a preset of simulate/materials.hpp), else `fallback`.
Material materialOption(const Args& args, const Material& fallback);
// The number after option `name`, or fallback when absent; `what` names it in the error ("a length in mm").
double numberOption(const Args& args, const std::string& name, double fallback, const std::string& what = "a number");
// A whole number from lo to hi after option `name`, or fallback when absent; `what` names it in the error ("an
// iteration count").
int intOption(const Args& args, const std::string& name, int fallback, int lo, int hi, const std::string& what);
// --max-memory MB, else the machine's physical memory: the budget a computation's predicted need is
// checked against before it starts (util/memory_budget.hpp).
double memoryBudgetOption(const Args& args);
// The most memory this process has held so far (peak resident set), in bytes.
double peakResidentBytes();

// The folder of the billow executable (examples are looked up beside the build; io/design_json.hpp).
std::string executableDir();
// A design file made into its scene (pattern/design_scene.hpp loadDesignScene, examples beside the build), with
// a line on stderr unless quiet.
std::unique_ptr<DesignScene> openDesignScene(const std::string& path, bool quiet);
// The design's "fabrication" settings (io/export_options_json.hpp), the defaults where it has none; an error names
// them.
ExportOptions designFabrication(const Design& design);
// Writes the bytes (text, or a PDF) as they are; an error names the file.
void writeFile(const std::string& path, const std::string& bytes);
// Segmentation and pattern problems on stderr, one a line ("  error: ...").
void printProblems(const std::vector<SegmentationProblem>& problems);

int checkCommand(const std::vector<std::string>& args);
int inflateCommand(const std::vector<std::string>& args);
int exampleCommand(const std::vector<std::string>& args);
int exportCommand(const std::vector<std::string>& args);
int segmentCommand(const std::vector<std::string>& args);
int designCommand(const std::vector<std::string>& args);
int suggestCommand(const std::vector<std::string>& args);

}  // namespace billow::cli
