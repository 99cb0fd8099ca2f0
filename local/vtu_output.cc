#include "vtu_output.h"

#include "vtu.h"

namespace pumpd::local
{
  namespace
  {
    /// The field's values at the material nodes.
    VtuField at_nodes(const std::string &name, const std::vector<double> &field, const std::vector<std::size_t> &nodes)
    {
      VtuField f{name, 1, {}};
      f.values.reserve(nodes.size());
      for (std::size_t i : nodes)
        f.values.push_back(field[i]);
      return f;
    }
  } // namespace

  void write_vtu(const std::string &path, const PdModel &model, const State &s)
  {
    const auto &nodes = model.nodes();
    VtuGrid     grid;
    VtuField    displacement{"displacement", 3, {}};
    for (std::size_t c = 0; c < nodes.size(); ++c)
      {
        const auto p = model.lattice().position(nodes[c]);
        grid.points.insert(grid.points.end(), {p.x, p.y});
        grid.add_cell(std::int64_t(c), 1, 1);
        displacement.values.insert(displacement.values.end(), {s.ux[nodes[c]], s.uy[nodes[c]], 0.});
      }
    std::vector<double> layer(s.ux.size(), 0.);
    for (std::size_t i : model.boundary_layer())
      layer[i] = 1.;
    grid.point_data = {std::move(displacement), at_nodes("damage", model.damage(s), nodes),
                       at_nodes("stretch_ratio_Z", model.stretch_ratio(s), nodes),
                       at_nodes("energy_density", model.energy_density(s), nodes),
                       at_nodes("boundary_layer", layer, nodes)};
    grid.active_scalars = "damage";
    grid.active_vectors = "displacement";
    pumpd::write_vtu(path, grid);
  }

  void write_vtu(PvdSeries &series, const PdModel &model, const State &s)
  {
    const std::string file = series.next_file();
    write_vtu(series.path_of(file), model, s);
    series.add(s.time, file);
  }
} // namespace pumpd::local
