// pumpd: runs a scene from a deal.II parameter file.
//   pumpd <scene.prm>          run it
//   pumpd --print-parameters   every parameter with default, allowed range and documentation
//   pumpd --help
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <sstream>
#include <string>

#include "error.h"
#include "full_pd.h"
#include "global_local.h"
#include "lefm_growth.h"
#include "parameters.h"
#include "pd_edge_crack.h"

namespace
{
  const char *usage = "usage: pumpd <scene.prm> | --print-parameters | --help\n"
                      "  Runs the scene described by a deal.II ParameterHandler file; see prm/ for examples\n"
                      "  and --print-parameters for every parameter, its default and its allowed range.\n";

  /// One line: deal.II's multi-line messages folded.
  std::string one_line(const std::string &text)
  {
    std::istringstream in(text);
    std::string        word, line;
    while (in >> word)
      line += (line.empty() ? "" : " ") + word;
    return line;
  }

  int run(const std::string &file)
  {
    dealii::ParameterHandler prm;
    pumpd::coupling::declare_parameters(prm);
    prm.parse_input(file);
    const auto type = pumpd::coupling::scene_type(prm);
    if (type == "pd-edge-crack")
      {
        const auto r = pumpd::coupling::run_edge_crack(pumpd::coupling::read_edge_crack(prm), std::cout);
        std::cout << "crack growth onset at K/K_c = " << r.onset_k_over_kc << "; grown crack within "
                  << r.max_offset / r.spacing << " h of the symmetry line\n";
      }
    else if (type == "lefm-growth")
      {
        const auto r = pumpd::coupling::run_lefm_growth(pumpd::coupling::read_lefm_growth(prm), std::cout);
        const auto &end = r.path.back();
        std::cout << "crack path ends at (" << end.x << ", " << end.y << ") after " << r.increments
                  << " increments, length " << pumpd::geometry::length(r.path) << " m (" << r.stop_reason << "), "
                  << r.seconds << " s\n";
      }
    else if (type == "global-local")
      pumpd::coupling::run_global_local(pumpd::coupling::read_global_local(prm), std::cout);
    else if (type == "full-pd")
      pumpd::coupling::run_full_pd(pumpd::coupling::read_full_pd(prm), std::cout);
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  // MPI (one process) for the Trilinos solvers.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string arg = argc > 1 ? argv[1] : "--help";
  if (arg == "--help" || arg == "-h" || argc > 2)
    {
      std::cout << usage;
      return argc > 2 ? 1 : 0;
    }
  if (arg == "--print-parameters")
    {
      dealii::ParameterHandler prm;
      pumpd::coupling::declare_parameters(prm);
      prm.print_parameters(std::cout, dealii::ParameterHandler::Description);
      return 0;
    }
  try
    {
      return run(arg);
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      std::cerr << "pumpd: error in " << arg << ": " << one_line(info.str()) << "\n";
    }
  catch (const std::exception &e)
    {
      std::cerr << "pumpd: error in " << arg << ": " << one_line(e.what()) << "\n";
    }
  return 1;
}
