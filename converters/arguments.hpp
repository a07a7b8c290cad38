#pragma once
// A small command-line argument reader shared by the subcommands: positional arguments and
// --name value / --flag options, with one-line errors for unknown or malformed options. Each command
// describes itself once (CommandSpec: its forms, text and table of options); the parser, its --help and
// `cadnurbs --help` all read that one table, so they cannot disagree.
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "converters/limited_child.hpp"
#include "converters/walled_read.hpp"

namespace cadnurbs {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Arguments {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;  // --name value
  std::set<std::string> flags;                // --flag

  bool has(const std::string& name) const { return values.count(name) || flags.count(name); }
  std::string value(const std::string& name, const std::string& fallback = "") const;
  double number(const std::string& name, double fallback) const;  // refuses non-numbers
  int integer(const std::string& name, int fallback) const;        // refuses non-integers
};

// One option of a command. "output" is written and accepted as -o as well as --output.
struct OptionSpec {
  std::string name;   // without the "--"
  std::string value;  // the placeholder of its value, such as "D"; empty: a flag
  // What it does, lines already wrapped for the help column (22). Empty: the command's synopsis names
  // the option itself and its description tells what it does (no line of its own in --help).
  std::string help;
};

// A command as the parser, its --help and `cadnurbs --help` see it.
struct CommandSpec {
  std::string name;  // "convert"
  // What follows "cadnurbs NAME", one line per form of the command, such as "IN -o OUT [options]".
  // "[options]" stands for every option that no form names.
  std::string synopsis;
  std::string description;  // the paragraphs before the options
  std::vector<OptionSpec> options;  // --help is every command's flag besides
  std::string epilogue;     // the text after the options, may be empty
};

// --time-limit S and --memory-limit MB of convert, info and report: the limits of the STEP/IGES reads
// (read_limits).
const std::vector<OptionSpec>& read_limit_options();

// --reader native|occt (in read_limit_options; batch takes it alone).
const OptionSpec& step_reader_option();

// `options` followed by read_limit_options().
std::vector<OptionSpec> with_read_limits(std::vector<OptionSpec> options);

// --time-limit and --memory-limit as the limits of the reading child (converters/walled_read), the
// defaults where they are not given. Refuses (UsageError) a limit that is not positive, or a memory limit
// above 2^40 MB.
ProcessLimits read_limits(const Arguments& a);

// --reader: which STEP reader (UsageError for another value).
StepReaderChoice step_reader_choice(const Arguments& a);

// The options of `spec` that take a value take one ("-o" counts as "--output"), the others none; "--help"
// is a flag of every command. Throws UsageError "unknown option '--x' (see cadnurbs NAME --help)",
// "option --x needs a value", "option --x takes no value".
Arguments parse_arguments(const CommandSpec& spec, const std::vector<std::string>& args);

// The forms of the command, one or more lines each starting "cadnurbs NAME ", "[options]" spelled out as
// "[--name VALUE]" for each option, wrapped at 100 columns with the continuation lines indented to the
// first argument. No newline at the end.
std::string command_synopsis(const CommandSpec& spec);

// `cadnurbs NAME --help`: "usage: " and the synopsis, the description, a block per option with help
// ("  --deviation D       that maximum ...", further lines indented to the help column), the epilogue.
std::string command_help(const CommandSpec& spec);

}  // namespace cadnurbs
