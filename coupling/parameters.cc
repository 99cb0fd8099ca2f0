#include "parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

#include "error.h"
#include "nucleation.h"
#include "output_volume.h"
#include "parameter_file.h"
#include "parameter_table.h"
#include "scene_lengths.h"

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
    auto set = parse_parameter_file(prm, file);
    p.cycle.scene_file = ParameterTable::of_handler(prm, std::move(set));
    return p;
  }

  Parameters parse_parameters(const std::string &text)
  {
    Parameters               p;
    dealii::ParameterHandler prm;
    p.add_parameters(prm);
    auto set = entries_set_in(text);
    prm.parse_input_from_string(text);
    p.cycle.scene_file = ParameterTable::of_handler(prm, std::move(set));
    return p;
  }

  void derive_lengths(Parameters &p, const Scene &scene, std::ostream *out)
  {
    if (p.scene.length_defaults != "scene")
      return;
    const auto                lengths = measure_lengths(scene);
    std::vector<std::string>  derived;
    const bool       pd = p.method != "lefm-growth", global = p.method != "full-pd";
    const Parameters defaults;
    // An entry keeps its value where the scene file set it, or where code changed it from its
    // default (a test, a study's rung).
    const auto derive = [&](const std::string &path, double &entry, double default_value, double value,
                            const std::string &why = "", bool used = true) {
      if (p.cycle.scene_file.is_set(path) || entry != default_value)
        return;
      entry = value;
      if (used)
        derived.push_back(path.substr(path.rfind('/') + 1) + " " + to_text(value * 1e3, 3) + " mm" +
                        (why.empty() ? "" : " (" + why + ")"));
    };
    namespace f = proportion;
    const auto horizon = scene_horizon(lengths);
    derive("Peridynamics/Horizon", p.pd.horizon, defaults.pd.horizon, horizon.value, horizon.bound, pd);
    const double delta = p.pd.horizon;
    if (p.method == "global-local")
      {
        derive("Global-local/Box size", p.cycle.box.size, defaults.cycle.box.size, f::box_size * delta);
        derive("Global-local/Box margin", p.cycle.box.margin, defaults.cycle.box.margin, f::box_margin * delta);
        derive("Global-local/Maximum box size", p.cycle.box.max_size, defaults.cycle.box.max_size, f::max_box_size * delta);
        derive("Global-local/Maximum advance", p.cycle.exchange.max_advance, defaults.cycle.exchange.max_advance, f::max_advance * delta);
        derive("Global-local/Minimum advance", p.cycle.exchange.min_advance, defaults.cycle.exchange.min_advance, f::min_advance * delta);
        derive("Global-local/Near distance", p.cycle.exchange.near_distance, defaults.cycle.exchange.near_distance, f::near_distance * delta);
      }
    const auto increment = scene_growth_increment(lengths);
    derive("LEFM growth/Growth increment", p.lefm.growth_increment, defaults.lefm.growth_increment, increment.value, increment.bound,
           p.method == "lefm-growth");
    const double tip_scale = p.method == "lefm-growth" ? p.lefm.growth_increment : delta;
    derive("Global/Tip enrichment radius", p.global.tip_radius, defaults.global.tip_radius,
           std::max(std::min(f::tip_radius * tip_scale, 0.5 * lengths.tip_clearance),
                    lengths.tip_cell / std::pow(2., p.global.refinement_levels)),
           "", global);
    derive("Global/Refinement radius", p.global.refinement_radius, defaults.global.refinement_radius,
           std::max(f::refinement_radius * tip_scale, p.global.tip_radius), "", global);
    derive("Global/Refinement trail", p.global.refinement_trail, defaults.global.refinement_trail, f::refinement_trail * tip_scale, "", global);
    if (out && !derived.empty())
      {
        *out << "lengths from the scene (L = " << to_text(lengths.body_side * 1e3, 3) << " mm";
        if (std::isfinite(lengths.crack_length))
          *out << ", a = " << to_text(lengths.crack_length * 1e3, 3) << " mm";
        if (std::isfinite(lengths.hole_radius))
          *out << ", R = " << to_text(lengths.hole_radius * 1e3, 3) << " mm";
        *out << "):";
        for (std::size_t k = 0; k < derived.size(); ++k)
          *out << (k == 0 ? " " : ", ") << derived[k];
        *out << std::endl;
      }
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

  void run(const Parameters &given, std::ostream &out)
  {
    Parameters p = given;
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
    derive_lengths(p, scene, &out);
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
