#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <thread>

#include "converters/arguments.hpp"
#include "converters/batch/convert_library.hpp"
#include "converters/commands.hpp"
#include "converters/file_formats.hpp"

namespace cadnurbs {

const CommandSpec& batch_command_spec() {
  static const CommandSpec spec = {
      "batch",
      "IN_DIR -o OUT_DIR [options]\n"
      "--merge OUT_DIR",
      "Converts every part under IN_DIR (a file named as an input format, or holding one when its name\n"
      "says nothing), each in a worker process of its own, N at a time, into OUT_DIR's mirror of IN_DIR:\n"
      "OUT_DIR/<part>.<ext> for each output and OUT_DIR/<part>.json, the part's record (the report's\n"
      "schema, docs/report.md, plus a \"batch\" object: content hash, options, seconds). Each part is read\n"
      "once; its record holds what converting it told: faces, repairs, fallbacks, each output's bytes raw\n"
      "and gzip'd and its deviation bound; --measure adds the report's full comparison. A part that fails,\n"
      "crashes, hangs or runs out of memory is recorded with its reason and the batch goes on. A second\n"
      "run skips the parts whose record has the same content hash and options, except those that\n"
      "exceeded a time or memory limit, which it does again. Ends with the combined\n"
      "report: OUT_DIR/report.md, report.json, report.csv and report.html (library-wide charts).",
      {
          {"output", "OUT_DIR", ""},
          {"jobs", "N", "workers at a time (default: the number of cores)"},
          step_reader_option(),
          {"to", "EXT,...", "outputs per part (default x3dv; any output extension of convert)"},
          {"inputs", "EXT,...",
           "only the parts of these input formats (such as step,iges: a library's\n"
           "shipped meshes left out); default: every part"},
          {"measure", "",
           "each record is the report's full comparison of representations (as `report`\n"
           "measures them: NURBS, .cnb, NURSS, meshes, Draco, meshoptimizer, read back)"},
          {"deviation", "D", "--measure's maximum mesh deviation D in millimetres (default 1)"},
          {"timeout", "S", "per part, wall and CPU time (default 300)"},
          {"memory", "MB", "per part, address space (default 4096)"},
          {"shard", "K/N",
           "only the K-th (0 to N-1) of N disjoint slices of the parts (cluster array\n"
           "tasks); its report is OUT_DIR/report-K-of-N.*"},
          {"merge", "", "the combined report of every record under OUT_DIR (all shards')"},
          {"site", "DIR",
           "also the library as a static site in DIR (adds cnb to --to): index.html (every\n"
           "part's picture, family and bytes, the site's size against the meshes the\n"
           "library ships beside the parts), a page per part showing it in the browser\n"
           "viewer, the shared viewer and module once; serve DIR over HTTP"},
      },
      "Exit status 0 when every part converted, 3 when some failed.",
  };
  return spec;
}

namespace {

constexpr int kSomeFailed = 3;

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  for (size_t start = 0, comma; start <= text.size(); start = comma + 1) {
    comma = text.find(',', start);
    if (comma == std::string::npos) comma = text.size();
    if (comma > start) items.push_back(text.substr(start, comma - start));
  }
  return items;
}

// "0.0123x": a share of another size, to three significant digits.
std::string ratio_text(long part, long whole) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3gx", static_cast<double>(part) / whole);
  return text;
}

}  // namespace

int run_batch(const std::vector<std::string>& args, const CommandContext& context) {
  const Arguments a = parse_arguments(batch_command_spec(), args);
  if (a.has("help")) {
    std::cout << command_help(batch_command_spec());
    return 0;
  }
  if (a.has("merge")) {
    if (a.positional.size() != 1) throw UsageError("--merge needs the one OUT_DIR of the shards");
    if (a.has("site"))
      throw UsageError("--site needs the library: run batch IN_DIR -o OUT_DIR --site DIR (done parts are reused)");
    const BatchSummary s = merge_batch(a.positional[0]);
    std::cout << a.positional[0] << ": " << s.parts << " parts, " << s.failed
              << " failed; report.md, report.json, report.csv, report.html\n";
    return s.failed > 0 ? kSomeFailed : 0;
  }
  if (a.positional.size() != 1 || !a.has("output")) throw UsageError("needs one IN_DIR and -o OUT_DIR (see --help)");
  BatchOptions options;
  options.read.brep.walled = context.read_wall;
  options.read.brep.step_reader = step_reader_choice(a);
  options.read.brep.child_stage_hook = context.child_stage_hook;
  options.read.brep.always_exec = context.always_exec;
  options.in_dir = a.positional[0];
  options.out_dir = a.value("output");
  options.jobs = a.integer("jobs", static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  if (options.jobs < 1) throw UsageError("--jobs must be at least 1");
  if (a.has("to")) options.targets = split_list(a.value("to"));
  if (options.targets.empty()) throw UsageError("--to needs at least one extension");
  for (auto& target : options.targets) {
    if (target.front() == '.') target.erase(0, 1);
    output_format("x." + target);  // refuses an unknown one before any work
  }
  if (a.has("site")) {
    options.site_dir = a.value("site");
    if (std::find(options.targets.begin(), options.targets.end(), "cnb") == options.targets.end()) options.targets.push_back("cnb");
    if (a.has("shard")) throw UsageError("--site needs the whole library, not a --shard");
  }
  if (a.has("inputs")) {
    for (const auto& name : split_list(a.value("inputs"))) options.inputs.push_back(&named_input_format(name));
    if (options.inputs.empty()) throw UsageError("--inputs needs at least one extension");
  }
  options.measure = a.has("measure");
  options.deviation_mm = a.number("deviation", options.deviation_mm);
  if (!(options.deviation_mm > 0)) throw UsageError("--deviation must be a positive number of millimetres");
  options.seconds = a.number("timeout", options.seconds);
  if (!(options.seconds > 0)) throw UsageError("--timeout must be a positive number of seconds");
  options.megabytes = a.integer("memory", static_cast<int>(options.megabytes));
  if (options.megabytes < 64) throw UsageError("--memory must be at least 64 MB");
  if (a.has("shard")) {
    const std::string shard = a.value("shard");
    const size_t slash = shard.find('/');
    try {
      if (slash == std::string::npos) throw std::invalid_argument("no slash");
      options.shard = std::stoi(shard.substr(0, slash));
      options.shards = std::stoi(shard.substr(slash + 1));
    } catch (const std::exception&) {
      throw UsageError("--shard needs K/N, such as 0/4, not '" + shard + "'");
    }
    if (options.shards < 1 || options.shard < 0 || options.shard >= options.shards)
      throw UsageError("--shard K/N needs 0 <= K < N, not '" + shard + "'");
  }
  options.progress_bar = ::isatty(2);
  const BatchSummary s = convert_library(options);
  std::cout << options.out_dir << ": " << s.parts << " parts: " << s.converted << " converted now, " << s.reused
            << " done before, " << s.failed << " failed\n";
  if (s.site) {
    const SiteTotals& t = s.site->totals;
    std::cout << options.site_dir << ": " << s.site->pages << " part pages (" << s.site->pictures_failed
              << " without a picture), " << t.site() << " bytes (" << t.gzip << " gzip'd): shared " << t.shared
              << ", pages " << t.pages << ", .cnb " << t.cnb << ", pictures " << t.thumbnails << ", index " << t.index << "\n";
    if (t.parts_with_library_mesh > 0)
      std::cout << "the library's meshes of " << t.parts_with_library_mesh << " of these parts: " << t.library_mesh
                << " bytes (" << t.library_mesh_gzip << " gzip'd); the site is " << ratio_text(t.site(), t.library_mesh)
                << " of them (" << ratio_text(t.gzip, t.library_mesh_gzip) << " gzip'd)\n";
  }
  return s.failed > 0 ? kSomeFailed : 0;
}

}  // namespace cadnurbs
