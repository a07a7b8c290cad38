// Every command's table of options (CommandSpec) against what users read: each option in the command's
// --help, in `cadnurbs --help` and in README.md's command-line synopsis; and the parser refusing what the
// table does not hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <sstream>

#include "command_fixture.hpp"
#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "formats/common/file_io.hpp"

using namespace cadnurbs;

namespace {

using test::CommandResult;
class HelpText : public test::CommandTest {};

// How users write the option: "-o" for the output, "--name" otherwise.
std::string written(const OptionSpec& option) { return option.name == "output" ? "-o" : "--" + option.name; }

// `text` has `word` on its own: not as the start of a longer option ("--to" of "--tolerance", "--memory" of
// "--memory-limit") nor as the end of one ("-o" of "--output").
bool has_word(const std::string& text, const std::string& word) {
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const auto part_of_name = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-'; };
    const size_t end = at + word.size();
    if ((at == 0 || !part_of_name(text[at - 1])) && (end == text.size() || !part_of_name(text[end]))) return true;
  }
  return false;
}

bool names(const std::string& text, const OptionSpec& option) {
  return has_word(text, written(option)) || has_word(text, "--" + option.name);
}

// The synopsis of `command` in a usage listing: each line that starts (after blanks and "usage: ") with
// "cadnurbs COMMAND", with the indented lines that continue it.
std::string synopsis_of(const std::string& text, const std::string& command) {
  std::istringstream lines(text);
  std::string block;
  bool inside = false;
  for (std::string line; std::getline(lines, line);) {
    std::string start = line.substr(std::min(line.find_first_not_of(' '), line.size()));
    if (start.rfind("usage: ", 0) == 0) start = start.substr(7);
    const std::string head = "cadnurbs " + command;
    if (start.rfind(head, 0) == 0 && (start.size() == head.size() || start[head.size()] == ' ')) {
      inside = true;
    } else if (line.empty() || line[0] != ' ' || start.rfind("cadnurbs ", 0) == 0) {
      inside = false;
    }
    if (inside) block += line + "\n";
  }
  return block;
}

// README.md's "## Command line" section.
std::string readme_command_line() {
  const std::string readme = read_file(std::string(CADNURBS_SOURCE_DIR) + "/README.md");
  const size_t start = readme.find("\n## Command line");
  if (start == std::string::npos) return "";
  return readme.substr(start, readme.find("\n## ", start + 1) - start);
}

}  // namespace

TEST_F(HelpText, EachCommandsHelpIsMadeFromItsTableAndNamesEveryOption) {
  for (const Command& command : commands()) {
    const CommandSpec& spec = command.spec();
    const CommandResult r = run(spec.name + " --help");
    ASSERT_EQ(r.status, 0) << spec.name << ": " << r.err;
    EXPECT_EQ(r.out, command_help(spec)) << spec.name;
    const std::string usage = synopsis_of(r.out, spec.name);
    EXPECT_EQ(r.out.rfind("usage: cadnurbs " + spec.name + " ", 0), 0u) << r.out;
    for (const OptionSpec& option : spec.options) {
      EXPECT_TRUE(names(usage, option)) << spec.name << " --help's usage lacks " << written(option) << ":\n" << r.out;
      if (option.help.empty()) {
        // No line of its own: the command's own synopsis names it and its description tells the rest.
        EXPECT_TRUE(names(spec.synopsis, option)) << spec.name << " " << written(option) << " is explained nowhere";
      } else {
        EXPECT_NE(r.out.find("\n  " + written(option) + (option.value.empty() ? "" : " " + option.value)),
                  std::string::npos)
            << spec.name << " --help has no line for " << written(option) << ":\n" << r.out;
      }
    }
  }
}

TEST_F(HelpText, MainHelpListsEveryOptionOfEveryCommandInTheTablesOrder) {
  const CommandResult r = run("--help");
  ASSERT_EQ(r.status, 0) << r.err;
  size_t previous = 0;
  for (const Command& command : commands()) {
    const CommandSpec& spec = command.spec();
    const std::string synopsis = synopsis_of(r.out, spec.name);
    ASSERT_FALSE(synopsis.empty()) << "cadnurbs --help lacks " << spec.name << ":\n" << r.out;
    const size_t at = r.out.find("  cadnurbs " + spec.name + " ");
    EXPECT_GT(at, previous) << spec.name << " out of order";
    previous = at;
    for (const OptionSpec& option : spec.options)
      EXPECT_TRUE(names(synopsis, option)) << "cadnurbs --help lacks " << spec.name << " " << written(option);
  }
  // A command it does not know: the same listing after the one-line complaint.
  const CommandResult unknown = run("nonsense");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_EQ(unknown.err, "cadnurbs: unknown command 'nonsense'\n" + r.out);
}

TEST_F(HelpText, ReadmeListsEveryOptionOfEveryCommand) {
  const std::string section = readme_command_line();
  ASSERT_FALSE(section.empty()) << "README.md has no \"## Command line\" section";
  std::string missing;
  for (const Command& command : commands()) {
    const CommandSpec& spec = command.spec();
    const std::string synopsis = synopsis_of(section, spec.name);
    if (synopsis.empty()) {
      missing += "\n  README.md lacks the command " + spec.name;
      continue;
    }
    for (const OptionSpec& option : spec.options)
      if (!names(synopsis, option)) missing += "\n  README.md lacks " + spec.name + " " + written(option);
  }
  EXPECT_TRUE(missing.empty()) << "the synopsis lines (\"cadnurbs COMMAND ...\" and their indented continuations) "
                                  "of README.md's Command line section:"
                               << missing;
}

TEST_F(HelpText, ParsingRefusesWhatTheTableDoesNotHoldAndTakesWhatItHolds) {
  for (const Command& command : commands()) {
    const CommandSpec& spec = command.spec();
    try {
      parse_arguments(spec, {"--x"});
      ADD_FAILURE() << spec.name << " took --x";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()), "unknown option '--x' (see cadnurbs " + spec.name + " --help)");
    }
    for (const OptionSpec& option : spec.options) {
      const Arguments a = option.value.empty() ? parse_arguments(spec, {"--" + option.name})
                                               : parse_arguments(spec, {written(option), "7"});
      EXPECT_TRUE(a.has(option.name)) << spec.name << " " << written(option);
      if (!option.value.empty()) {
        EXPECT_EQ(a.value(option.name), "7") << spec.name << " " << written(option);
      }
    }
    EXPECT_TRUE(parse_arguments(spec, {"--help"}).has("help")) << spec.name;
  }
  const CommandResult r = run("convert a.stl -o b.wrl --x");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "cadnurbs convert: unknown option '--x' (see cadnurbs convert --help)\n");
}
