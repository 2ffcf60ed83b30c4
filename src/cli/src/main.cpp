// `knots`: the project's command-line tool. One subcommand per file
// (cmd_*.cpp). Exit status: 0 success, 1 a numerical or topological failure
// reported by the command, 2 bad input (one line on stderr).
#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ek/core/commit.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/paths.hpp"

namespace {

struct Command {
  const char* name;
  int (*run)(int, char**);
  const char* help;
};

const std::vector<Command>& commands() {
  static const std::vector<Command> list = {
#define EK_COMMAND(name, fn, help) {name, ek::cli::fn, help},
#include "command_list.inc"
#undef EK_COMMAND
  };
  return list;
}

void print_usage(std::ostream& out) {
  out << "usage: knots COMMAND [ARGS] (knots COMMAND --help for details), knots --version\n\ncommands:\n";
  for (const auto& c : commands()) {
    std::string name = c.name;
    name.resize(12, ' ');
    out << "  " << name << c.help << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && !std::strcmp(argv[1], "--version")) {
    std::cout << "knots " << ek::project_version() << " (commit " << ek::source_commit() << ")" << std::endl;
    return 0;
  }
  if (argc < 2 || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "help")) {
    print_usage(argc < 2 ? std::cerr : std::cout);
    return argc < 2 ? 2 : 0;
  }
  for (const auto& c : commands()) {
    if (std::strcmp(argv[1], c.name) != 0) continue;
    try {
      return c.run(argc, argv);
    } catch (const ek::InputError& e) {
      std::cerr << "knots " << c.name << ": error: " << ek::one_line(e.what()) << std::endl;
      return 2;
    } catch (const ek::TopologyError& e) {
      std::cerr << "knots " << c.name << ": topology error: " << ek::one_line(e.what()) << std::endl;
      return 1;
    } catch (const std::invalid_argument& e) {
      std::cerr << "knots " << c.name << ": error: " << ek::one_line(e.what()) << std::endl;
      return 2;
    } catch (const std::bad_alloc&) {
      std::cerr << "knots " << c.name << ": error: out of memory" << std::endl;
      return 1;
    } catch (const std::exception& e) {
      std::cerr << "knots " << c.name << ": internal error: " << ek::one_line(e.what()) << std::endl;
      return 1;
    }
  }
  std::cerr << "knots: error: unknown command '" << argv[1] << "' (see knots --help)" << std::endl;
  return 2;
}
