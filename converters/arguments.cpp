#include "converters/arguments.hpp"

#include <cmath>

#include "converters/walled_read.hpp"

namespace cadnurbs {

std::string Arguments::value(const std::string& name, const std::string& fallback) const {
  auto it = values.find(name);
  return it == values.end() ? fallback : it->second;
}

double Arguments::number(const std::string& name, double fallback) const {
  auto it = values.find(name);
  if (it == values.end()) return fallback;
  size_t used = 0;
  double x = 0;
  try {
    x = std::stod(it->second, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != it->second.size() || !std::isfinite(x))
    throw UsageError("--" + name + " needs a number, not '" + it->second + "'");
  return x;
}

int Arguments::integer(const std::string& name, int fallback) const {
  const double x = number(name, fallback);
  if (x != std::floor(x)) throw UsageError("--" + name + " needs a whole number, not '" + values.at(name) + "'");
  return static_cast<int>(x);
}

const char* const kReadLimitHelp =
    "  --time-limit S      STEP/IGES: give up reading after S seconds, of wall or CPU time (default 120);\n"
    "                      OpenCASCADE reads in a child process, so a crash or a hang in it is reported\n"
    "  --memory-limit MB   STEP/IGES: the reading process's address-space limit (default 4096)\n";

void apply_read_limits(const Arguments& a) {
  ReadLimits& limits = read_limits();
  limits.seconds = a.number("time-limit", limits.seconds);
  if (!(limits.seconds > 0)) throw UsageError("--time-limit needs a positive number of seconds, not '" + a.value("time-limit") + "'");
  const double megabytes = a.number("memory-limit", static_cast<double>(limits.megabytes));
  if (!(megabytes >= 1 && megabytes <= 1099511627776.0) || megabytes != std::floor(megabytes))
    throw UsageError("--memory-limit needs a whole number of megabytes from 1, not '" + a.value("memory-limit") + "'");
  limits.megabytes = static_cast<long>(megabytes);
}

Arguments parse_arguments(const std::string& command, const std::vector<std::string>& args,
                          const std::set<std::string>& value_options, const std::set<std::string>& flag_options) {
  Arguments out;
  for (size_t i = 0; i < args.size(); ++i) {
    std::string a = args[i];
    if (a == "-o") a = "--output";
    if (a.rfind("--", 0) != 0 || a.size() == 2) {
      out.positional.push_back(a);
      continue;
    }
    std::string name = a.substr(2), value;
    const bool inline_value = name.find('=') != std::string::npos;
    if (inline_value) {
      value = name.substr(name.find('=') + 1);
      name = name.substr(0, name.find('='));
    }
    if (flag_options.count(name)) {
      if (inline_value) throw UsageError("option --" + name + " takes no value");
      out.flags.insert(name);
    } else if (value_options.count(name)) {
      if (!inline_value) {
        if (i + 1 >= args.size()) throw UsageError("option --" + name + " needs a value");
        value = args[++i];
      }
      out.values[name] = value;
    } else {
      throw UsageError("unknown option '--" + name + "' (see cadnurbs " + command + " --help)");
    }
  }
  return out;
}

}  // namespace cadnurbs
