#pragma once
// Entry points of the subcommands (argv[1] is the command name), one per
// cmd_<name>.cpp; declared for every command in command_list.inc.
namespace ek::cli {
int cmd_info(int argc, char** argv);
int cmd_embed(int argc, char** argv);
int cmd_invariants(int argc, char** argv);
int cmd_sample(int argc, char** argv);
int cmd_energy(int argc, char** argv);
int cmd_ccd(int argc, char** argv);
int cmd_relax(int argc, char** argv);
int cmd_similarity(int argc, char** argv);
int cmd_attributes(int argc, char** argv);
int cmd_explore(int argc, char** argv);
int cmd_dataset(int argc, char** argv);
int cmd_merge(int argc, char** argv);
int cmd_ledger(int argc, char** argv);
int cmd_describe(int argc, char** argv);
int cmd_cluster(int argc, char** argv);
int cmd_query(int argc, char** argv);
int cmd_search(int argc, char** argv);
int cmd_export(int argc, char** argv);
int cmd_site(int argc, char** argv);
int cmd_serve(int argc, char** argv);
int cmd_saddles(int argc, char** argv);
int cmd_transition(int argc, char** argv);
int cmd_transitions(int argc, char** argv);
int cmd_path(int argc, char** argv);
int cmd_connect(int argc, char** argv);
int cmd_load(int argc, char** argv);
int cmd_dynamics(int argc, char** argv);
}  // namespace ek::cli
