#pragma once
// Entry points of the subcommands (argv[1] is the command name).
namespace ek::cli {
#define EK_COMMAND(name, fn, help) int fn(int argc, char** argv);
#include "command_list.inc"
#undef EK_COMMAND
}  // namespace ek::cli
