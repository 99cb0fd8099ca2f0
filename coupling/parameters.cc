#include "parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <ostream>
#include <sstream>

#include "error.h"
#include "nucleation.h"
#include "output_volume.h"
#include "parameter_file.h"
#include "parameter_table.h"

namespace pumpd::coupling
{
  void Parameters::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Method");
    prm.add_parameter("Type", method,
                      "Which method computes the scene. lefm-growth: XFEM and the maximum hoop stress criterion, no PD "
                      "(sections Global, Crack growth, LEFM growth). global-local: XFEM drives a PD box at the crack "
                      "tip, the PD damage grows the crack (Global, Peridynamics, Crack growth, Global-local). full-pd: "
                      "the whole body as one PD body (Peridynamics, Crack growth, Full PD). pd-edge-crack: the PD "
                      "co-solver's check, a PD box driven by the Williams field of a rising K (Peridynamics, Edge "
                      "crack; from the scene only its material and output directory).",
                      dealii::Patterns::Selection("lefm-growth|global-local|full-pd|pd-edge-crack"));
    prm.leave_subsection();
    scene.add_parameters(prm);
    global.add_parameters(prm);
    pd.add_parameters(prm);
    growth.add_parameters(prm);
    initiation.add_parameters(prm);
    lefm.add_parameters(prm);
    cycle.add_parameters(prm);
    full_pd.add_parameters(prm);
    edge_crack.add_parameters(prm);
    study.add_parameters(prm);
  }

  Parameters read_parameters(const std::string &file)
  {
    Parameters               p;
    dealii::ParameterHandler prm;
    p.add_parameters(prm);
    parse_parameter_file(prm, file);
    p.cycle.scene_file = ParameterTable::of_handler(prm);
    return p;
  }

  Parameters parse_parameters(const std::string &text)
  {
    Parameters               p;
    dealii::ParameterHandler prm;
    p.add_parameters(prm);
    prm.parse_input_from_string(text);
    p.cycle.scene_file = ParameterTable::of_handler(prm);
    return p;
  }

  void check_against_scene(const Parameters &p, const Scene &scene)
  {
    const auto &body = scene.body.bounding_box();
    if (const double most = 0.1 * std::min(body.width(), body.height());
        !scene.body.holes().empty() && p.growth.hole_margin > most)
      throw InvalidParameter("Hole margin", to_text(p.growth.hole_margin),
                             "must be at most a tenth of the body's smaller side (" + to_text(most) + " m)");
    if (p.method != "full-pd")
      {
        check_tip_radius(scene, p.global);
        check_refinement(scene, p.global, p.scene.max_cells);
      }
    check_output_volume(p, &scene, p.scene.output_directory);
  }

  void run(const Parameters &p, std::ostream &out)
  {
    make_output_directory("Scene / Output directory", p.scene.output_directory);
    if (p.method == "pd-edge-crack")
      {
        check_output_volume(p, nullptr, p.scene.output_directory);
        const auto r = run_edge_crack({p.pd.material(p.scene.material), p.pd, p.edge_crack, p.scene.output_directory}, out);
        out << "crack growth onset at K/K_c = " << r.onset_k_over_kc << "; grown crack within "
            << r.max_offset / r.spacing << " h of the symmetry line\n";
        return;
      }
    const Scene scene = build_scene(p.scene, &out);
    check_against_scene(p, scene);
    if (scene.cracks.empty() && p.method == "global-local")
      run_global_local_from_initiation(scene, p.global_local_settings(), p.initiation, out);
    else if (scene.cracks.empty() && p.method == "lefm-growth")
      {
        report_initiation(find_initiation(scene, p.global, p.pd, p.initiation), scene, out);
        throw InvalidParameter("Initial cracks", "none",
                               "LEFM growth has no law for a crack to start (it grows a crack that is there): the "
                               "candidate sites are listed above" +
                                 std::string(scene.output_directory.empty()
                                               ? ""
                                               : " and in " + scene.output_directory + "/initiation_sites.csv") +
                                 "; give the crack to grow as Initial cracks, or let global-local or full PD start one");
      }
    else if (p.method == "lefm-growth")
      run_lefm_growth(scene, p.lefm_growth_settings(), out);
    else if (p.method == "global-local")
      run_global_local(scene, p.global_local_settings(), out);
    else
      run_full_pd(scene, p.full_pd_settings(), out);
  }
} // namespace pumpd::coupling
