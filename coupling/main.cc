// pumpd: runs a scene from a deal.II parameter file.
//   pumpd <scene.prm>          run it
//   pumpd --study <scene.prm>  its speed/accuracy trade: LEFM, the cycle at a ladder of settings,
//                              full PD (the section Study; study.h)
//   pumpd --print-parameters   every parameter with default, allowed range and documentation
//   pumpd --help
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>

#include <csignal>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include <unistd.h>

#include "error.h"
#include "parameters.h"
#include "program.h"
#include "study.h"

namespace
{
  const char *usage = "usage: pumpd <scene.prm> | --study <scene.prm> | --print-parameters | --help\n"
                      "  Runs the scene described by a deal.II ParameterHandler file (a specimen: its mesh, material,\n"
                      "  boundary conditions and cracks; and the method that computes it); see prm/ for examples\n"
                      "  and --print-parameters for every parameter, its default and its allowed range.\n"
                      "  --study: runs the scene by LEFM growth, by the global-local cycle at its settings and at a\n"
                      "  ladder of others, and by full PD (the section Study), and writes what each costs and where\n"
                      "  its crack goes (trade.csv, trade.md, trade.png) and the cheapest setting within a tolerance.\n";
  /// The PD kernel's OpenMP threads meet at barriers several times per force evaluation. A thread
  /// that spins there holds its core while its sibling waits for one: on a machine shared with
  /// other work the PD states then take several times as long (docs/peridynamics.md). libgomp
  /// reads its waiting policy once, at start-up, so pumpd starts itself again with the passive
  /// policy unless the user chose one. Only a process that runs PD threads starts again (it loads
  /// deal.II's libraries again): LEFM growth runs none, and a study's own process sets the policy
  /// for its runs, processes of their own that inherit it.
  void wait_passively_at_barriers(char **argv, bool runs_pd_threads)
  {
    if (std::getenv("OMP_WAIT_POLICY") != nullptr)
      return;
    setenv("OMP_WAIT_POLICY", "passive", 1);
    if (runs_pd_threads)
      execv("/proc/self/exe", argv);
  }
} // namespace

int main(int argc, char **argv)
{
  const std::string arg   = argc > 1 ? argv[1] : "";
  const bool        study = arg == "--study" && argc == 3;
  // deal.II on one thread (its assembly sums in one order: the same results on any machine).
  dealii::MultithreadInfo::set_thread_limit(1);
  if ((arg == "--help" || arg == "-h") && argc == 2)
    {
      std::cout << usage;
      return 0;
    }
  // Misuse: one line on stderr, the reason and the usage's first line.
  const auto misuse = [](const std::string &why) {
    std::cerr << "pumpd: " << why << "; " << std::string(usage).substr(0, std::string(usage).find('\n')) << "\n";
    return 1;
  };
  if (argc == 1)
    return misuse("no scene file");
  if (arg.rfind("-", 0) == 0 && arg != "--study" && arg != "--print-parameters" && arg != "--help" && arg != "-h")
    return misuse("unknown option " + arg);
  if ((argc > 2 && !study) || (arg == "--study" && !study))
    return misuse("wrong number of arguments");
  if (arg == "--print-parameters")
    {
      pumpd::coupling::Parameters p;
      dealii::ParameterHandler    prm;
      p.add_parameters(prm);
      prm.print_parameters(std::cout, dealii::ParameterHandler::Description);
      return 0;
    }
  const std::string file = study ? argv[2] : arg;
  try
    {
      if (study)
        {
          wait_passively_at_barriers(argv, false);
          pumpd::coupling::run_study(file, pumpd::this_executable(), std::cout);
        }
      else
        {
          const auto p = pumpd::coupling::read_parameters(file);
          if (p.method != "lefm-growth")
            wait_passively_at_barriers(argv, true);
          // MPI (one process) for the Trilinos solver only: its start-up is slow.
          std::optional<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
          if (p.global.linear_solver == "cg-amg")
            mpi.emplace(argc, argv, 1);
          pumpd::coupling::run(p, std::cout);
        }
      return 0;
    }
  catch (const pumpd::Interrupted &interrupted)
    {
      // One line, then the end the signal would have given (the shell sees 128 + signal).
      std::cout.flush();
      std::cerr << "pumpd: stopped in " << file << ": " << interrupted.what() << std::endl;
      std::signal(interrupted.signal, SIG_DFL);
      std::raise(interrupted.signal);
      return 128 + interrupted.signal;
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      std::cerr << "pumpd: error in " << file << ": " << pumpd::one_line(info.str()) << "\n";
    }
  catch (const std::exception &e)
    {
      std::cerr << "pumpd: error in " << file << ": " << pumpd::one_line(e.what()) << "\n";
    }
  return 1;
}
