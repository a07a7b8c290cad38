#pragma once
// A small command-line argument reader shared by the subcommands: positional arguments and
// --name value / --flag options, with one-line errors for unknown or malformed options.
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

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

// --time-limit S and --memory-limit MB of convert, info and report (value options of theirs): sets
// read_limits() (converters/walled_read) for the STEP/IGES reads. Refuses (UsageError) a limit that is not
// positive, or a memory limit above 2^40 MB.
void apply_read_limits(const Arguments& a);

// Their help lines.
extern const char* const kReadLimitHelp;

// `value_options` take a value ("-o" counts as "--output"); `flag_options` take none. Throws
// UsageError "<command>: unknown option '--x'" and the like.
Arguments parse_arguments(const std::string& command, const std::vector<std::string>& args,
                          const std::set<std::string>& value_options, const std::set<std::string>& flag_options);

}  // namespace cadnurbs
