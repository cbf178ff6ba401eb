// photowalk: one photo of a corridor to a true-scale 3D model you can walk through.
// main() only dispatches to the subcommands (editor/cli/cmd_*.cpp).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "editor/cli/command.h"

namespace {

void printOverview() {
  std::printf(
      "photowalk %s: one photo of a corridor to a true-scale 3D model you can walk through.\n\n"
      "usage: photowalk COMMAND [ARGS...]    (photowalk COMMAND --help for details)\n\ncommands:\n",
      PW_VERSION);
  std::vector<pw::editor::Command> all = pw::editor::commands();
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return std::strcmp(a.name, b.name) < 0; });
  for (const auto& c : all) std::printf("  %-9s %s\n", c.name, c.summary);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
    printOverview();
    return argc < 2 ? pw::editor::kExitFailure : pw::editor::kExitOk;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::printf("photowalk %s\n", PW_VERSION);
    return 0;
  }
  for (const auto& command : pw::editor::commands()) {
    if (std::strcmp(command.name, argv[1]) != 0) continue;
    std::vector<std::string> rest(argv + 2, argv + argc);
    if (std::find_if(rest.begin(), rest.end(), [](const std::string& a) { return a == "--help" || a == "-h"; }) !=
        rest.end()) {
      std::printf("%s", command.usage);
      return 0;
    }
    pw::editor::Args args(std::move(rest));
    try {
      return command.run(args);
    } catch (const std::exception& e) {
      // Commands return errors as values; this only catches what slipped through
      // (bad_alloc, a library's exception) so that the user still gets one line.
      return pw::editor::fail(std::string("internal: ") + e.what());
    }
  }
  return pw::editor::fail(std::string("unknown command '") + argv[1] + "'; run photowalk --help for the list");
}
