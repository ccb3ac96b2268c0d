// billow: the command-line tool. Each subcommand lives in its own cli/cmd_*.cpp.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "util/error.hpp"

namespace {

const billow::cli::Command* find(const std::string& name) {
  for (const auto& c : billow::cli::commands())
    if (name == c.name) return &c;
  return nullptr;
}

void printUsage(FILE* out) {
  std::fprintf(out, "billow: design inflatable structures (Skouras et al. 2014)\n\nusage: billow COMMAND [ARGS]\n\n");
  for (const auto& c : billow::cli::commands()) std::fprintf(out, "  %-10s %s\n", c.name, c.summary);
  std::fprintf(out, "\nRun 'billow COMMAND --help' for a command's options.\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
    printUsage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const auto* command = find(argv[1]);
  if (!command) {
    std::fprintf(stderr, "billow: unknown command '%s'\n\n", argv[1]);
    printUsage(stderr);
    return 2;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  try {
    return command->run(args);
  } catch (const billow::Error& e) {
    std::fprintf(stderr, "billow %s: %s\n", command->name, e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "billow %s: internal error: %s\n", command->name, e.what());
    return 3;
  }
}
