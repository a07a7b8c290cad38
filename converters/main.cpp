// cadnurbs: the command line. Thin: it picks the subcommand and turns errors into one line.
#include <iostream>
#include <map>

#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "converters/walled_read.hpp"

namespace {

const char* kUsage =
    "usage: cadnurbs COMMAND [options]\n"
    "commands:\n"
    "  convert IN -o OUT [--mesh] [--deviation D | --steps N] [--exact-nurbs] [--units U]\n"
    "                    [--display-deviation D] [--precision N] [--pretty] [--euclidean] [--self-contained]\n"
    "                    [--simplify D]\n"
    "  info    IN [--euclidean]\n"
    "  capping --shape NAME|all -o OUT [--path FILE --profile FILE] [--max-chord-deviation D]\n"
    "  report  IN... [--deviation D] [--format md|json|csv|html] [-o FILE] [--files DIR] [--records DIR] [--curve] [--simplify S]\n"
    "  normals IN.stl -o OUT [--crease-angle DEG] [--weld TOL]\n"
    "  fit-loop IN.stl -o CONTROL.obj [--surface LIMIT] [--control-vertices N] [--tolerance D] [--crease-angle DEG]\n"
    "  fit-path IN -o OUT --deviation D\n"
    "  batch   IN_DIR -o OUT_DIR [--jobs N] [--to EXT,...] [--deviation D] [--timeout S] [--memory MB] [--shard K/N]\n"
    "  batch   --merge OUT_DIR\n"
    "  demo    [-o DIR]\n"
    "'cadnurbs COMMAND --help' tells more.\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace cadnurbs;
  const std::map<std::string, int (*)(const std::vector<std::string>&)> commands = {
      {"convert", run_convert}, {"info", run_info}, {"capping", run_capping}, {"demo", run_demo}, {"report", run_report}, {"normals", run_normals}, {"fit-loop", run_fit_loop}, {"batch", run_batch},
      {"fit-path", run_fit_path}};
  if (argc < 2) {
    std::cerr << kUsage;
    return 2;
  }
  if (const std::string first = argv[1]; first == "--help" || first == "-h" || first == "help") {
    std::cout << kUsage;
    return 0;
  }
  // The hidden child side of the STEP/IGES wall (converters/walled_read): this executable serves it, so
  // its reads go through the wall.
  if (std::string(argv[1]) == "__read-brep") return run_read_brep_child(std::vector<std::string>(argv + 2, argv + argc));
  enable_read_wall();
  const auto command = commands.find(argv[1]);
  if (command == commands.end()) {
    std::cerr << "cadnurbs: unknown command '" << argv[1] << "'\n" << kUsage;
    return 2;
  }
  try {
    return command->second(std::vector<std::string>(argv + 2, argv + argc));
  } catch (const UsageError& e) {
    std::cerr << "cadnurbs " << argv[1] << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "cadnurbs " << argv[1] << ": " << e.what() << "\n";
    return 1;
  }
}
