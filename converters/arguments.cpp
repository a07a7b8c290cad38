#include "converters/arguments.hpp"

#include <cctype>
#include <cmath>

#include "converters/limited_child.hpp"

namespace cadnurbs {

namespace {

constexpr size_t kHelpColumn = 22;      // where the options' help starts
constexpr size_t kSynopsisWidth = 100;  // a synopsis line wraps before this

// How the option is written: "-o" for the output, "--name" for the rest.
std::string option_key(const OptionSpec& option) { return option.name == "output" ? "-o" : "--" + option.name; }

// "-o OUT", "--deviation D", "--mesh".
std::string option_label(const OptionSpec& option) {
  return option_key(option) + (option.value.empty() ? "" : " " + option.value);
}

// `text` holds `word` as a word of its own: after a blank, '[' or '|' and before none of [a-z0-9-], so
// that "--to" is not found in "--tolerance" nor "--memory" in "--memory-limit".
bool holds_word(const std::string& text, const std::string& word) {
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool starts = at == 0 || std::string(" [|\n").find(text[at - 1]) != std::string::npos;
    const size_t end = at + word.size();
    const bool ends = end == text.size() || !(std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-');
    if (starts && ends) return true;
  }
  return false;
}

bool names_option(const std::string& text, const OptionSpec& option) {
  return holds_word(text, option_key(option)) || holds_word(text, "--" + option.name);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

// The words of a synopsis line, a bracketed group such as "[--deviation D]" one word.
std::vector<std::string> synopsis_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  int depth = 0;
  for (const char c : line) {
    if (c == ' ' && depth == 0) {
      if (!word.empty()) words.push_back(word);
      word.clear();
      continue;
    }
    depth += (c == '[') - (c == ']');
    word += c;
  }
  if (!word.empty()) words.push_back(word);
  return words;
}

std::string with_newline(const std::string& text) {
  return text.empty() || text.back() == '\n' ? text : text + "\n";
}

}  // namespace

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

const OptionSpec& step_reader_option() {
  static const OptionSpec option = {
      "reader", "native|occt",
      "STEP: our own reader only, or OpenCASCADE's only (default: our own, and OpenCASCADE's\n"
      "for a file it cannot read, saying which entity sent the file there)"};
  return option;
}

const std::vector<OptionSpec>& read_limit_options() {
  static const std::vector<OptionSpec> options = {
      {"time-limit", "S",
       "STEP/IGES: give up reading after S seconds, of wall or CPU time (default 120);\n"
       "OpenCASCADE reads in a child process, so a crash or a hang in it is reported"},
      {"memory-limit", "MB", "STEP/IGES: the reading process's address-space limit (default 4096)"},
      step_reader_option(),
  };
  return options;
}

std::vector<OptionSpec> with_read_limits(std::vector<OptionSpec> options) {
  options.insert(options.end(), read_limit_options().begin(), read_limit_options().end());
  return options;
}

ProcessLimits read_limits(const Arguments& a) {
  ProcessLimits limits;
  limits.seconds = a.number("time-limit", limits.seconds);
  if (!(limits.seconds > 0)) throw UsageError("--time-limit needs a positive number of seconds, not '" + a.value("time-limit") + "'");
  const double megabytes = a.number("memory-limit", static_cast<double>(limits.megabytes));
  if (!(megabytes >= 1 && megabytes <= 1099511627776.0) || megabytes != std::floor(megabytes))
    throw UsageError("--memory-limit needs a whole number of megabytes from 1, not '" + a.value("memory-limit") + "'");
  limits.megabytes = static_cast<long>(megabytes);
  return limits;
}

StepReaderChoice step_reader_choice(const Arguments& a) {
  if (!a.has("reader")) return StepReaderChoice::native_then_occt;
  if (a.value("reader") == "native") return StepReaderChoice::native;
  if (a.value("reader") == "occt") return StepReaderChoice::occt;
  throw UsageError("--reader takes native or occt, not '" + a.value("reader") + "'");
}

Arguments parse_arguments(const CommandSpec& spec, const std::vector<std::string>& args) {
  std::set<std::string> value_options, flag_options = {"help"};
  for (const OptionSpec& option : spec.options) (option.value.empty() ? flag_options : value_options).insert(option.name);
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
      throw UsageError("unknown option '--" + name + "' (see cadnurbs " + spec.name + " --help)");
    }
  }
  return out;
}

std::string command_synopsis(const CommandSpec& spec) {
  std::string options;
  for (const OptionSpec& option : spec.options)
    if (!names_option(spec.synopsis, option)) options += (options.empty() ? "[" : " [") + option_label(option) + "]";
  const std::string name = "cadnurbs " + spec.name;
  std::vector<std::string> lines;
  for (const std::string& form : spec.synopsis.empty() ? std::vector<std::string>{""} : lines_of(spec.synopsis)) {
    lines.push_back(name);
    for (const std::string& word : synopsis_words(form))
      for (const std::string& piece : word == "[options]" ? synopsis_words(options) : std::vector<std::string>{word}) {
        if (lines.back().size() > name.size() && lines.back().size() + 1 + piece.size() > kSynopsisWidth)
          lines.push_back(std::string(name.size(), ' '));  // continued under the first argument
        lines.back() += " " + piece;
      }
  }
  std::string text;
  for (const std::string& line : lines) text += (text.empty() ? "" : "\n") + line;
  return text;
}

std::string command_help(const CommandSpec& spec) {
  std::string text;
  for (const std::string& line : lines_of(command_synopsis(spec)))
    text += (text.empty() ? "usage: " : "       ") + line + "\n";  // the other forms under the first
  text += with_newline(spec.description);
  for (const OptionSpec& option : spec.options) {
    if (option.help.empty()) continue;
    const std::string label = "  " + option_label(option);
    // A label too long for the column gets a line of its own.
    text += label.size() + 2 > kHelpColumn ? label + "\n" + std::string(kHelpColumn, ' ')
                                           : label + std::string(kHelpColumn - label.size(), ' ');
    const std::vector<std::string> lines = lines_of(option.help);
    for (size_t i = 0; i < lines.size(); ++i) text += (i == 0 ? "" : std::string(kHelpColumn, ' ')) + lines[i] + "\n";
  }
  return text + with_newline(spec.epilogue);
}

}  // namespace cadnurbs
