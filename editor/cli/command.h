// The photowalk program's subcommands. Each lives in its own cmd_*.cpp and registers
// itself with PW_COMMAND; main() only dispatches.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.h"

namespace pw::editor {

// Exit codes shared by all commands.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;   // bad input, failed work: a one-line "error: ..." was printed
inline constexpr int kExitNotFound = 2;  // the command ran but found nothing (detect: no corridor)
inline constexpr int kExitUnsure = 3;     // written, but a person should check it (detect: an unsure best guess)

// Command-line arguments of one subcommand. Options are looked up by name (and
// alias); what is left, not starting with '-', are positionals. finish() reports
// options nobody asked for, so a typo is an error rather than silently ignored.
class Args {
 public:
  explicit Args(std::vector<std::string> args) : args_(std::move(args)), used_(args_.size(), false) {}

  bool flag(std::string_view name, std::string_view alias = {});
  // "--size 640x480" or "--size=640x480". A missing value is recorded as an error.
  std::optional<std::string> value(std::string_view name, std::string_view alias = {});
  // Every occurrence, in order (for repeatable options).
  std::vector<std::string> values(std::string_view name, std::string_view alias = {});
  std::vector<std::string> positionals();
  Status finish() const;

 private:
  std::vector<std::string> args_;
  std::vector<bool> used_;
  std::string error_;
};

Result<std::pair<int, int>> parseSize(std::string_view text, std::string_view optionName);
Result<double> parseNumber(std::string_view text, std::string_view optionName);
Result<int> parsePositiveInt(std::string_view text, std::string_view optionName);

// An input of a command, for checkNotAnInput: what it is ("the model", "the shot's
// photo") and its path.
struct NamedInput {
  std::string what;
  std::string path;
};

// An error when `output` (given with `option`, e.g. "-o") is the same file as one of
// `inputs`, through symbolic and hard links too: a command never writes over what it
// reads. An output that does not exist yet is none of them.
Status checkNotAnInput(const std::string& output, std::string_view option, const std::vector<NamedInput>& inputs);

// An error unless `path` ends in .png, .jpg or .jpeg (any case): where a command
// writes an image, a name such as m.wrl is a mistake, not a wish.
Status checkImageExtension(const std::string& path, std::string_view option);

struct Command {
  const char* name;
  const char* summary;  // one line for `photowalk --help`
  const char* usage;    // the full `photowalk NAME --help` text
  int (*run)(Args& args);
};

const std::vector<Command>& commands();

struct CommandRegistrar {
  explicit CommandRegistrar(const Command& command);
};

// Prints "error: MESSAGE" on stderr and returns kExitFailure. Every line these print
// is one line: control characters in MESSAGE (a newline or NUL in a quoted path or
// token) are escaped (base/input_file.h: escapeControls).
int fail(std::string_view message);
// "warning: MESSAGE" and "note: MESSAGE" on stderr, as fail() prints.
void printWarning(std::string_view message);
void printNote(std::string_view message);

}  // namespace pw::editor

#define PW_COMMAND(id, ...) \
  static const ::pw::editor::CommandRegistrar pwCommandRegistrar_##id{::pw::editor::Command{__VA_ARGS__}}
