#include <filesystem>
#include <iostream>

#include "converters/arguments.hpp"
#include "converters/capping_files.hpp"
#include "converters/commands.hpp"
#include "converters/file_formats.hpp"
#include "formats/common/file_io.hpp"
#include "samples/capping_shapes.hpp"

namespace cadnurbs {

const CommandSpec& capping_command_spec() {
  static const CommandSpec spec = [] {
    std::string set;
    for (const auto& ext : capping_extensions()) set += " " + ext;
    return CommandSpec{
        "capping",
        "--shape NAME -o OUT [options]",
        "Generates a stair capping (seed 001, ch. 4): the handrail profile swept along a path as one\n"
        "exact rational quadratic NURBS, the handrail connections closed by trimmed planar lids.",
        {
            {"shape", "NAME", "capping-90, capping-end, capping-post, capping-moulded, or 'all'"},
            {"output", "OUT",
             "a file (" + extension_list(false) + ")\n"
             "or, with a trailing '/' or an existing directory, a folder that\n"
             "gets NAME with each of" + set},
            {"path", "FILE",
             "with --profile FILE: the outlines of the path and of the profile in the\n"
             "text format of samples/shapes/README.md (instead of a bundled shape; NAME\n"
             "names the result)"},
            {"profile", "FILE", "the profile's outline, with --path"},
            {"max-chord-deviation", "D",
             "STL: arcs divided so no chord is farther than D mm from its arc\n"
             "(default 0.1)"},
            {"without-lids", "",
             "NURBS: the swept body alone, connections left open (for viewers\n"
             "that ignore trimming; one file, not a folder)"},
        },
        "",
    };
  }();
  return spec;
}

int run_capping(const std::vector<std::string>& args, const CommandContext&) {
  const Arguments a = parse_arguments(capping_command_spec(), args);
  if (a.has("help")) {
    std::cout << command_help(capping_command_spec());
    return 0;
  }
  if (!a.has("shape") || !a.has("output") || !a.positional.empty())
    throw UsageError("needs --shape NAME and -o OUT (see --help)");
  const double chord = a.number("max-chord-deviation", 0.1);
  if (!(chord > 0)) throw UsageError("--max-chord-deviation must be positive");
  if (a.has("path") != a.has("profile")) throw UsageError("--path and --profile go together");

  std::vector<CappingDefinition> cappings;
  if (a.has("path")) {
    cappings.push_back(parse_capping(a.value("shape"), read_file(a.value("path")), a.value("path"),
                                     read_file(a.value("profile")), a.value("profile")));
  } else if (a.value("shape") == "all") {
    for (const auto& name : capping_shape_names()) cappings.push_back(bundled_capping(name));
  } else {
    cappings.push_back(bundled_capping(a.value("shape")));
  }

  const std::string out = a.value("output");
  const bool to_folder = out.back() == '/' || std::filesystem::is_directory(out);
  if (!to_folder && cappings.size() > 1) throw UsageError("--shape all needs a folder for -o");
  for (const auto& capping : cappings) {
    if (to_folder) {
      for (const auto& path : write_capping_set(capping, out, chord)) std::cout << path << "\n";
    } else {
      write_capping(capping, out, chord, !a.has("without-lids"));
      std::cout << out << "\n";
    }
  }
  return 0;
}

}  // namespace cadnurbs
