// cadnurbs: the command line (converters/command_line.hpp).
#include "converters/command_line.hpp"

int main(int argc, char** argv) { return cadnurbs::run_command_line(argc, argv); }
