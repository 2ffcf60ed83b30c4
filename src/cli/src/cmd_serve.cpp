// knots serve (DATASET.h5 | LEDGER | FOLDER) [--port P] [--cut C] [--title T]
#include <signal.h>

#include <atomic>
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/errors.hpp"
#include "ek/site/server.hpp"
#include "ek/site/site.hpp"

namespace ek::cli {
namespace {

std::atomic<bool> g_stop{false};

extern "C" void on_stop_signal(int) { g_stop.store(true); }

}  // namespace

int cmd_serve(int argc, char** argv) {
  std::string file, title;
  SiteOptions options;
  ServeOptions serve;
  ArgParser args("serve", "(DATASET.h5 | LEDGER | FOLDER) [--port P] [--cut C] [--title T]");
  args.positional("DATASET", &file, "data-set file, ledger file, or folder of ledgers (*.ledger.h5)");
  args.option("--port", &serve.port, "TCP port on 127.0.0.1 (0: any free port)");
  args.option("--cut", &options.cut, "distance cut of the table's distinct states and the sliders' start, in [0, 1]");
  args.option("--title", &title, "title of the site (default: the file's or folder's name)");
  if (!args.parse(argc, argv)) return 0;
  options.title = title;
  options.validate();
  if (serve.port < 0 || serve.port > 65535) throw InputError("--port must be in 0..65535");
  SiteServer server(build_site(file, options), serve);
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  std::cout << "serving " << file << " at http://127.0.0.1:" << server.port() << "/ (Ctrl-C stops)" << std::endl;
  server.serve(g_stop);
  std::cout << "stopped" << std::endl;
  return 0;
}

}  // namespace ek::cli
