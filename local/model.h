// The PD body in a box: lattice, bonds, the force kernel and the derived fields.
//
// A node exists where the lattice meets the body (outside holes); a bond exists where its segment
// stays in the body (clear of holes and re-entrant corners); a bond across a pre-existing crack
// polyline starts broken. Nodes
// within one horizon of a box edge that lies inside the body form the boundary layer and take
// prescribed displacements (BoundaryLayer); edges on the body outline are free surfaces.
// Besides the layer, prescribed regions (PrescribedRegion: supports, loading pads) fix one or both
// displacement components of the nodes in a disk or box (RegionDisplacement sets their values); a
// roller fixes uy and leaves ux free. The free masks are per component.
//
// Units: force densities f [N/m^3], energy densities [J/m^3], energies per unit thickness [J/m].
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "body.h"
#include "lattice.h"
#include "material.h"

namespace pumpd::local
{
  /// What a model on this lattice and stencil and a run on it hold [bytes]: per stored node 24
  /// doubles (state, masks, the integrators' and the cycle's copies), per bond of the half stencil
  /// 5 bits (existence, initial cracks, no-fail zones, broken in two states).
  double estimated_model_bytes(const Lattice &grid, const Stencil &st);

  /// A model's memory against this machine's [bytes]: estimated_model_bytes, and the 0.8
  /// available_memory() it may take. PdModel refuses a lattice that needs more.
  struct ModelMemory
  {
    double needed = 0., available = 0.;
  };
  ModelMemory model_memory(const Lattice &grid, const Stencil &st);

  /// Where the PD box sits: the body it cuts out of, the box, and the cracks already there.
  struct Region
  {
    geometry::Body                  body;
    geometry::Box                   box;
    std::vector<geometry::Polyline> cracks;
  };

  /// A set of nodes with prescribed displacement components, besides the boundary layer: the
  /// material nodes inside `area` and, for a disk, within `radius` of `centre` (area is then the
  /// disk's bounding box); for a band, within `radius` of its `edges` (a named boundary of the
  /// body); for a shape, where `inside` holds (a named region of the body's mesh). fix_x / fix_y
  /// say which components are prescribed: a pin fixes both, a roller on a horizontal edge only uy.
  /// The values come from RegionDisplacement (boundary_layer.h) or stay where the state has them.
  struct PrescribedRegion
  {
    std::string                                  name; ///< for messages ("Pin support", ...)
    geometry::Box                                area;
    geometry::Point                              centre;
    double                                       radius = 0.; ///< disk or band; 0 with no edges: the box `area`
    std::vector<std::array<geometry::Point, 2>>  edges;
    std::function<bool(geometry::Point)>         inside;
    bool                                         fix_x = true, fix_y = true;
    /// >= 0: a no-fail zone. Bonds with an end within this distance [m] of the region (the disk's
    /// radius, or the box, grown by it) stay linear elastic: force a S instead of a S exp(-beta
    /// |xi| S^2), never fail, count as intact for damage. A support or load pad concentrates
    /// stress far beyond the PD strength (~K_c / sqrt(delta)) and would otherwise crush. < 0: none.
    double elastic_margin = -1.;

    static PrescribedRegion disk(std::string name, geometry::Point centre, double radius, bool fix_x, bool fix_y);
    static PrescribedRegion box(std::string name, const geometry::Box &area, bool fix_x, bool fix_y);
    static PrescribedRegion band(std::string name, std::vector<std::array<geometry::Point, 2>> edges, double width,
                                 bool fix_x, bool fix_y);
    static PrescribedRegion shape(std::string name, const geometry::Box &area,
                                  std::function<bool(geometry::Point)> inside, bool fix_x, bool fix_y);
    /// Grown: the region's nodes and those within grown_by of it (of its box, for a shape).
    bool contains(geometry::Point p, double grown_by = 0.) const;
    /// What the region is, for messages.
    std::string description() const;
  };

  /// Everything that changes in a run. Arrays use the lattice's storage index.
  struct State
  {
    std::vector<double>        ux, uy, vx, vy, fx, fy;
    std::vector<std::uint64_t> broken; ///< bit (k, i): bond from node i along offset k is gone
    double                     time          = 0.;
    std::uint64_t              step          = 0;
    double                     dissipated    = 0.; ///< energy of failed bonds [J/m]
    double                     external_work = 0.; ///< work of the boundary layer on the body [J/m]
  };

  class PdModel
  {
  public:
    /// horizon_ratio m = delta / h. Throws InvalidParameter (h <= 0, m < 2, box not inside the
    /// body, crack polyline outside the body, a prescribed region that fixes no component, has a
    /// negative or non-finite radius, or holds no material node) with the parameter's name and
    /// allowed range.
    PdModel(const MaterialParameters &material, double horizon, int horizon_ratio,
            const Region &region, const std::vector<PrescribedRegion> &prescribed = {});

    const LiptonMaterial &material() const { return mat; }
    const Lattice        &lattice() const { return grid; }
    const Stencil        &stencil() const { return st; }
    const Region         &region() const { return reg; }
    double                node_volume() const { return volume; }
    /// The material node nearest x.
    std::size_t nearest_node(geometry::Point x) const;

    /// Nodes that carry material, in storage order.
    const std::vector<std::size_t> &nodes() const { return active_nodes; }
    /// Nodes of the boundary layer (a subset of nodes()).
    const std::vector<std::size_t> &boundary_layer() const { return layer_nodes; }
    /// 1 for nodes whose two components move under the equation of motion, 0 elsewhere (ghosts,
    /// holes, layer, and nodes of a prescribed region with either component fixed).
    const std::vector<double> &free_mask() const { return free; }
    /// Per component: 1 where ux (uy) moves under the equation of motion, 0 where it is prescribed
    /// (layer, prescribed regions fixing it) or there is no node. The integrators use these.
    const std::vector<double> &free_mask_x() const { return free_x; }
    const std::vector<double> &free_mask_y() const { return free_y; }
    /// The prescribed regions as given, and the material nodes of region r (storage order).
    const std::vector<PrescribedRegion> &prescribed_regions() const { return regions; }
    const std::vector<std::size_t>      &prescribed_nodes(std::size_t r) const { return region_nodes.at(r); }
    /// Nodes with at least one prescribed component (layer and regions), in storage order.
    const std::vector<std::size_t> &constrained_nodes() const { return constrained; }
    /// Force the constraints exert on the body through the nodes of region r [N/m]: minus the sum
    /// of the bond force densities times the node volume (in equilibrium it balances them; only
    /// the fixed components are meaningful). Uses the forces in s (last compute_forces).
    geometry::Point reaction(const State &s, std::size_t r) const;

    /// Zero displacement and velocity, bonds broken where they do not exist or cross a crack.
    State initial_state() const;

    /// Bond forces into s.fx, s.fy (force densities); bonds beyond the break stretch fail and
    /// their energy moves to s.dissipated. Two threads split the rows deterministically: the
    /// result does not depend on the thread count. Bonds of no-fail zones (elastic_margin) are
    /// corrected to the linear force after the kernel, in one serial pass over them.
    void compute_forces(State &s) const;

    /// Silling-Askari bound sqrt(2 rho / sum_j c_ij / |xi_ij|) on the Verlet time step.
    double stable_time_step() const;
    /// Sum over the full stencil of the bond stiffness a_k / |xi_k| [N/m^4]: the diagonal scale
    /// used by the stability bound and by dynamic relaxation.
    double stiffness_scale() const { return stiffness; }

    double elastic_energy(const State &s) const;
    double kinetic_energy(const State &s) const;
    /// Per node: weighted fraction of the node's existing bonds that have failed: broken for good,
    /// or softened past the inflection stretch S_c (Lipton's fracture set: such a bond has
    /// spent most of its fracture energy; by 3 S_c, 99 %).
    std::vector<double> damage(const State &s) const;
    /// Per node: Z = max over its existing bonds that soften (material.h) of |S| / S_c(|xi|).
    std::vector<double> stretch_ratio(const State &s) const;
    /// Per node: the same over the bonds that shorten (zero where bonds do not soften in compression).
    std::vector<double> compressive_stretch_ratio(const State &s) const;
    /// Per node: elastic energy density W(x).
    std::vector<double> energy_density(const State &s) const;
    /// Count of bonds of the half stencil between existing nodes that are not broken.
    std::size_t intact_bonds(const State &s) const;
    /// Number of bonds (half stencil) kept linear elastic by no-fail zones.
    std::size_t linear_bond_count() const { return linear_k.size(); }

    std::size_t bit_plane_words() const { return plane_words; }
    bool        bond_exists(std::size_t k, std::size_t i) const
    {
      return (exists[k * plane_words + i / 64] >> (i % 64)) & 1u;
    }
    static bool bit(const std::vector<std::uint64_t> &bits, std::size_t word, std::size_t i)
    {
      return (bits[word + i / 64] >> (i % 64)) & 1u;
    }

  private:
    template <bool linear_in_compression>
    void forces_in_rows(State &s, std::size_t row_begin, std::size_t row_end, double &dissipated) const;
    template <class BondVisitor>
    void for_each_existing_bond(BondVisitor &&visit) const;
    /// Per stencil offset: the bond's inflection stretch (Lipton), which depends on its length.
    std::vector<double> inflection_stretches() const;

    LiptonMaterial             mat;
    Lattice                    grid;
    Stencil                    st;
    Region                     reg;
    double                     volume;
    std::vector<double>        force_coeff;  ///< a_k = 4 C beta q_k / (pi delta^3), q_k = h^2 weight_k
    std::vector<double>        energy_coeff; ///< C q_k / (pi delta^3): W contribution per unit g/C
    double                     stiffness;
    std::size_t                plane_words;
    std::vector<std::uint64_t> exists;   ///< static bond existence bits, layout of State::broken
    std::vector<std::uint64_t> precrack; ///< bonds cut by the initial cracks
    std::vector<std::size_t>   active_nodes, layer_nodes, constrained;
    std::vector<double>        free, free_x, free_y;
    std::vector<std::uint64_t> linear_bits; ///< no-fail bonds, layout of State::broken (empty: none)
    std::vector<std::uint32_t> linear_k;    ///< no-fail bonds: stencil offset and node
    std::vector<std::size_t>   linear_i;
    void                       correct_linear_bonds(State &s) const;
    /// Per node: the largest |S| / S_c over its bonds that soften (only those that shorten and are
    /// not in a no-fail zone, if shortening_only).
    std::vector<double> largest_stretch_ratio(const State &s, bool shortening_only) const;
    bool                       is_linear(std::size_t k, std::size_t i) const
    {
      return !linear_bits.empty() && bit(linear_bits, k * plane_words, i);
    }
    std::vector<PrescribedRegion>         regions;
    std::vector<std::vector<std::size_t>> region_nodes;
  };
} // namespace pumpd::local
