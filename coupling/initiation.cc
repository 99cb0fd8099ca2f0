#include "initiation.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <stdexcept>

#include "csv.h"
#include "error.h"
#include "strength.h"

namespace pumpd::coupling
{
  void InitiationSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Initiation");
    prm.add_parameter("Margin", margin,
                      "A scene without an initial crack lists where one would start: the largest ratio of the largest "
                      "principal stress to the PD strength, and every local maximum of the ratio (none larger within "
                      "a horizon) within this fraction of it (0.1: within 10 %); global-local forms a crack in a PD "
                      "box at each of them.",
                      dealii::Patterns::Double(0., 1.));
    prm.add_parameter("Point clearance", point_clearance,
                      "No site lies within this many horizons (or cells of the point, where those are larger) of a "
                      "point force or a point support: the field of a point condition is singular, and the stress "
                      "the mesh gives next to it belongs to the idealisation of a contact as a point.",
                      dealii::Patterns::Double(0., 100.));
    prm.add_parameter("First load factor", first_load_factor,
                      "Global-local on a scene without a crack: lambda / lambda_i of the first PD state of the "
                      "nucleation box at a site (lambda_i: sigma_1 = sigma_s there); the states rise by the "
                      "section Global-local's Load increment up to its Maximum load factor, both in units of lambda_i.",
                      dealii::Patterns::Double(0.05, 1.));
    prm.leave_subsection();
  }

  namespace
  {
    /// sigma_1 and the angle of its direction.
    struct Principal
    {
      double stress, angle;
    };

    bool in_any(geometry::Point x, const std::vector<geometry::Circle> &disks)
    {
      return std::any_of(disks.begin(), disks.end(),
                         [&](const geometry::Circle &c) { return geometry::norm(x - c.centre) < c.radius; });
    }

    Principal principal(const global::NodalStress &s)
    {
      const double mean = 0.5 * (s.xx + s.yy), half = 0.5 * (s.xx - s.yy);
      return {mean + std::sqrt(half * half + s.xy * s.xy), 0.5 * std::atan2(2. * s.xy, s.xx - s.yy)};
    }
    /// A disk about every point of a point condition, of radius max(at_least, cells times the
    /// size of the cells at the point).
    std::vector<geometry::Circle> point_disks(const conditions::Conditions            &c,
                                              const std::vector<global::NodalStress> &vertices, double at_least,
                                              double cells)
    {
      std::vector<geometry::Circle> disks;
      const auto                    add = [&](const conditions::Place &place) {
        if (place.kind != conditions::Place::Kind::point)
          return;
        for (const auto &x : place.points)
          {
            const auto nearest = std::min_element(vertices.begin(), vertices.end(), [&](const auto &a, const auto &b) {
              return geometry::norm(a.at - x) < geometry::norm(b.at - x);
            });
            disks.push_back({x, std::max(at_least, cells * nearest->cell_size)});
          }
      };
      for (const auto &d : c.displacements)
        add(d.place);
      for (const auto &f : c.forces)
        add(f.place);
      return disks;
    }
  } // namespace

  std::vector<InitiationSite> candidate_sites(const std::vector<global::NodalStress> &stress, double strength,
                                              double margin, double horizon, const std::vector<geometry::Circle> &left_out)
  {
    std::vector<double> ratio(stress.size());
    std::vector<bool>   eligible(stress.size());
    std::size_t         top = 0;
    for (std::size_t i = 0; i < stress.size(); ++i)
      {
        ratio[i]    = principal(stress[i]).stress / strength;
        eligible[i] = !in_any(stress[i].at, left_out);
        if (eligible[i] && (!eligible[top] || ratio[i] > ratio[top]))
          top = i;
      }
    if (stress.empty() || !eligible[top])
      throw std::invalid_argument("candidate_sites: no vertex outside the disks left out");
    if (ratio[top] <= 0.)
      throw InvalidParameter("Boundary conditions", "no tension",
                             "the largest principal stress is nowhere positive, so no crack starts (largest ratio to "
                             "the strength per unit load factor " +
                               to_text(ratio[top]) + " at " + geometry::to_text(stress[top].at) + ")");

    // Only the vertices outside the disks left out are compared, so that the largest of them is
    // the first site. Those within the margin can be sites; each is compared with every vertex
    // within its reach (a horizon, or its cells where they are larger), ties going to the lower
    // index.
    // The vertices lie in square buckets of a horizon (or of the mean vertex spacing, if larger).
    geometry::Box box{stress[0].at.x, stress[0].at.y, stress[0].at.x, stress[0].at.y};
    for (const auto &s : stress)
      box = {std::min(box.x_min, s.at.x), std::min(box.y_min, s.at.y), std::max(box.x_max, s.at.x),
             std::max(box.y_max, s.at.y)};
    const double size = std::max(horizon, std::sqrt(box.width() * box.height() / stress.size()));
    const int    nx = int(box.width() / size) + 1, ny = int(box.height() / size) + 1;
    const auto   column = [&](double x) { return std::clamp(int((x - box.x_min) / size), 0, nx - 1); };
    const auto   row    = [&](double y) { return std::clamp(int((y - box.y_min) / size), 0, ny - 1); };
    std::vector<std::vector<std::size_t>> bucket(std::size_t(nx) * ny);
    for (std::size_t i = 0; i < stress.size(); ++i)
      if (eligible[i])
        bucket[std::size_t(row(stress[i].at.y)) * nx + column(stress[i].at.x)].push_back(i);

    const double                floor = (1. - margin) * ratio[top];
    std::vector<InitiationSite> sites;
    for (std::size_t i = 0; i < stress.size(); ++i)
      {
        if (!eligible[i] || ratio[i] < floor)
          continue;
        const geometry::Point x       = stress[i].at;
        const double          reach   = std::max(horizon, stress[i].cell_size);
        bool                  maximum = true;
        for (int r = row(x.y - reach); r <= row(x.y + reach) && maximum; ++r)
          for (int c = column(x.x - reach); c <= column(x.x + reach) && maximum; ++c)
            for (const std::size_t j : bucket[std::size_t(r) * nx + c])
              if (j != i && (ratio[j] > ratio[i] || (ratio[j] == ratio[i] && j < i)) &&
                  geometry::norm(stress[j].at - x) <= reach)
                {
                  maximum = false;
                  break;
                }
        if (!maximum)
          continue;
        const Principal p = principal(stress[i]);
        sites.push_back({stress[i].at, p.stress, ratio[i], 1. / ratio[i], {std::cos(p.angle), std::sin(p.angle)}});
      }
    std::sort(sites.begin(), sites.end(), [](const InitiationSite &a, const InitiationSite &b) { return a.ratio > b.ratio; });
    return sites;
  }

  Initiation find_initiation(const Scene &scene, const GlobalSettings &global, const PeridynamicsSettings &pd,
                             const InitiationSettings &settings)
  {
    const auto                 &m = scene.material;
    const local::LiptonMaterial material(pd.material(m), pd.horizon);
    if (std::abs(m.poisson_ratio - material.poisson_ratio()) > 1e-9)
      throw InvalidParameter("Poisson's ratio", to_text(m.poisson_ratio),
                             std::string("a scene without a crack is judged against the strength of bond-based "
                                         "peridynamics, which has nu = ") +
                               (m.plane_strain ? "1/4 in plane strain" : "1/3 in plane stress") + ": set it in Scene/Material");

    Initiation result;
    result.strength = local::peak_stress(material, local::StrainPath::uniaxial_stress).stress;
    GlobalProblem problem(scene, global);
    problem.solve_uncracked();
    auto stress = problem.elasticity().nodal_stresses();
    for (auto &s : stress)
      {
        s.xx /= problem.load_factor();
        s.yy /= problem.load_factor();
        s.xy /= problem.load_factor();
      }
    const auto left_out = point_disks(scene.conditions, stress, settings.point_clearance * pd.horizon,
                                      settings.point_clearance);
    if (std::all_of(stress.begin(), stress.end(), [&](const global::NodalStress &s) { return in_any(s.at, left_out); }))
      throw InvalidParameter("Point clearance", to_text(settings.point_clearance),
                             "leaves no vertex of the mesh outside the disks around the point conditions: lower it");
    result.sites = candidate_sites(stress, result.strength, settings.margin, pd.horizon, left_out);
    if (!scene.output_directory.empty())
      {
        std::filesystem::create_directories(scene.output_directory);
        problem.write_vtu(scene.output_directory + "/initiation.vtu");
      }
    return result;
  }

  void report_initiation(const Initiation &initiation, const Scene &scene, std::ostream &out)
  {
    const std::size_t shown = 10;
    out << "initiation: no initial crack; the largest principal stress against the PD strength in uniaxial stress, "
        << to_text(initiation.strength, 4) << " Pa: " << initiation.sites.size() << " candidate site"
        << (initiation.sites.size() == 1 ? "" : "s") << " (largest ratio first)\n";
    for (std::size_t k = 0; k < initiation.sites.size() && k < shown; ++k)
      {
        const auto &s = initiation.sites[k];
        // Angles from x in (-90, 90] degrees, to a tenth.
        const double angle = std::round(1800. / M_PI * std::atan2(s.direction.y, s.direction.x)) / 10.;
        const double crack = angle > 0. ? angle - 90. : angle + 90.;
        out << "  site " << k + 1 << ": " << geometry::to_text(s.position) << ", lambda_i = " << to_text(s.load_factor, 4)
            << ", sigma_1 at " << to_text(angle, 4) << " degrees from x: a crack at " << to_text(crack, 4)
            << " degrees\n";
      }
    if (initiation.sites.size() > shown)
      out << "  and " << initiation.sites.size() - shown << " more in initiation_sites.csv\n";
    write_initiation_sites(initiation, scene);
  }

  void write_initiation_sites(const Initiation &initiation, const Scene &scene, const std::vector<SiteOutcome> &outcomes)
  {
    if (scene.output_directory.empty())
      return;
    std::filesystem::create_directories(scene.output_directory);
    const bool with_outcomes = outcomes.size() == initiation.sites.size() && !outcomes.empty();
    CsvFile    csv(scene.output_directory + "/initiation_sites.csv",
                   std::string("site,x_m,y_m,load_factor,sigma1_per_unit_load_pa,ratio_per_unit_load,direction_x,direction_y") +
                     (with_outcomes ? ",checked,formed,formed_load_factor,crack" : ""));
    for (std::size_t k = 0; k < initiation.sites.size(); ++k)
      {
        const auto &s = initiation.sites[k];
        if (!with_outcomes)
          csv.row(k + 1, s.position.x, s.position.y, s.load_factor, s.stress, s.ratio, s.direction.x, s.direction.y);
        else
          {
            const auto &o = outcomes[k];
            csv.row(k + 1, s.position.x, s.position.y, s.load_factor, s.stress, s.ratio, s.direction.x, s.direction.y,
                    int(o.checked), int(o.formed), o.load_factor, o.crack);
          }
      }
  }
} // namespace pumpd::coupling
