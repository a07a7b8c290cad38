#include "converters/arguments.hpp"

#include <cmath>

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
