// Private to global/: the data behind EnrichedElasticity (pimpl), shared by its .cc files.
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "cut_cell.h"
#include "elasticity.h"

namespace pumpd::global
{
  enum class NodeKind
  {
    standard,
    heaviside,
    tip
  };

  /// One enrichment block of a node: the Heaviside function of crack `crack` (tip < 0; 2 unknowns
  /// from `start`, shift[0] = H(x_p)) or the four branch functions of its tip `tip` (8 unknowns,
  /// shift = F_j(x_p)). A node carries at most one block per crack, in crack order.
  struct NodeEnrichment
  {
    unsigned int          crack = 0;
    int                   tip   = -1;
    unsigned int          start = 0;
    std::array<double, 4> shift{};
  };

  /// One scalar basis function of a cell: sum_v weight[v] N_v(x) (psi(x) - shift), carried by the
  /// two unknowns dof (x) and dof + 1 (y). kind: -1 standard (psi = 1, no shift), 0 Heaviside of
  /// crack `crack`, 1..4 branch function F_kind of tip `tip` of crack `crack`.
  struct LocalFunction
  {
    unsigned int          dof  = 0;
    int                   kind = -1;
    unsigned int          tip  = 0;
    unsigned int          crack = 0;
    double                shift = 0.;
    std::array<double, 4> weight{};
  };

  /// The crack sides of a set of points: side[q * stride + c] = +-1 for point q and crack c
  /// (stride = max(1, number of cracks); without a crack every side is +1).
  using Sides = std::vector<int>;

  /// Half the distance between the two tips of a crack (infinity for a crack with fewer): the
  /// interaction integral's domain about a tip ends there. Each node carries the branch functions
  /// of its nearest tip, so beyond it the enriched field is the other tip's, and a domain holding
  /// the other tip would add that tip's field to this one's K.
  inline double half_way_to_other_tip(const Crack &crack)
  {
    const auto &tips = crack.tips();
    return tips.size() == 2 ? 0.5 * geometry::norm(tips[0].position - tips[1].position)
                            : std::numeric_limits<double>::infinity();
  }

  /// The unknowns of a cell's functions: (x, y) of each, in order.
  inline std::vector<dealii::types::global_dof_index> unknowns_of(const std::vector<LocalFunction> &functions)
  {
    std::vector<dealii::types::global_dof_index> dofs;
    for (const auto &f : functions)
      {
        dofs.push_back(f.dof);
        dofs.push_back(f.dof + 1);
      }
    return dofs;
  }

  /// Values and gradients of a cell's local functions at the points of an FEValues object.
  struct BasisValues
  {
    std::vector<std::vector<double>>                value; ///< [function][point]
    std::vector<std::vector<dealii::Tensor<1, 2>>> grad;
  };

  struct CellData
  {
    bool                      cut          = false; ///< a piece of some crack lies in the cell
    std::vector<char>         cut_by;               ///< [crack]: a piece of this crack lies in the cell
    bool                      subdivided   = false; ///< integrated on its own sub-triangles
    bool                      has_tip      = false;
    bool                      tip_enriched = false; ///< some basis function carries F_j
    bool                      near_tip     = false; ///< within two diameters of a tip
    Sides                     side;                 ///< [crack]: side of the cell's centre
    std::vector<SubTriangle>  triangles;            ///< subdivided cells only
    Sides                     triangle_side;        ///< [triangle * stride + crack], of its centroid
    dealii::Quadrature<2>     quadrature;           ///< subdivided cells only
    std::vector<unsigned int> triangle_of_point;
  };

  struct EnrichedElasticity::Impl
  {
    Impl(dealii::Triangulation<2> &t, const ElasticMaterial &m, const EnrichmentSettings &s)
      : tria(t)
      , material(m)
      , settings(s)
      , fe(1)
      , dof_handler(t)
      , gauss(2)
      , gauss_tip(s.tip_order)
      , gauss_far_tip(s.far_tip_order)
    {}

    struct Dirichlet
    {
      unsigned int id;
      SidedField   value;
      bool         fix_x, fix_y;
    };
    struct VertexDirichlet
    {
      geometry::Point at, value;
      bool            fix_x, fix_y;
    };
    struct RegionDirichlet
    {
      unsigned int                                    material_id;
      std::function<geometry::Point(geometry::Point)> value;
      bool                                            fix_x, fix_y;
    };
    struct Traction
    {
      unsigned int                                                     id;
      std::function<geometry::Point(geometry::Point, geometry::Point)> value; ///< (x, outward normal)
    };
    struct PointLoad
    {
      geometry::Point at, force;
    };

    void         setup();
    void         assemble();
    SolveReport  solve(const SolverSettings &solver);
    unsigned int count(NodeKind k) const;
    /// [crack][node]: int |grad phi_p|^2 over the side of crack c that node p is not on, for the
    /// (c, p) marked in `wanted` (0 elsewhere).
    std::vector<std::vector<double>> far_side_energy(const std::vector<std::vector<char>> &wanted) const;

    /// The cell's basis: standard and enriched functions of the nodes its vertices depend on.
    std::vector<LocalFunction> local_functions(const dealii::DoFHandler<2>::active_cell_iterator &cell) const;
    /// The cell's quadrature (sub-triangles on cut cells, higher Gauss where branch functions live).
    const dealii::Quadrature<2> &quadrature(const dealii::DoFHandler<2>::active_cell_iterator &cell) const;
    /// max(1, number of cracks): the stride of Sides.
    unsigned int stride() const { return std::max<std::size_t>(1, cracks.size()); }
    /// The sides of the points of fv, which uses the cell's own quadrature: on a sub-triangle of a
    /// cell a crack cuts, the triangle's side of that crack; elsewhere the crack's level set.
    void sides_at(const dealii::DoFHandler<2>::active_cell_iterator &cell, const dealii::FEValuesBase<2> &fv,
                  Sides &side) const;
    /// The sides of x: each crack's level set, or `on_crack` where x lies on that crack (within
    /// `tolerance` of its level set's zero).
    void sides_of(const Point &x, int on_crack, double tolerance, Sides &side) const;
    /// Values and gradients of the local functions at the points of fv; side holds the crack
    /// sides of every point (decide H and the sign of theta).
    void evaluate(const dealii::FEValuesBase<2> &fv, const std::vector<LocalFunction> &functions,
                  const Sides &side, BasisValues &out) const;
    /// u_h and grad u_h (rows d u_x, d u_y) at the points of fv.
    void field(const dealii::FEValuesBase<2> &fv, const std::vector<LocalFunction> &functions,
               const Sides &side, std::vector<dealii::Tensor<1, 2>> &u,
               std::vector<dealii::Tensor<2, 2>> &grad) const;

    geometry::Point              displacement(geometry::Point x, int side) const;
    /// The nodes (indices into `nodes`) carrying the scalar dofs of the faces with this id.
    std::vector<unsigned int>    boundary_nodes(unsigned int boundary_id) const;
    /// sum over the nodes of a(u_h, phi_p e_c) less the point loads there.
    geometry::Point              reaction(const std::vector<unsigned int> &node_set) const;
    void                         prepare_point_evaluation(const std::vector<Point> &points, const std::vector<int> &side);
    std::vector<Point>           evaluate_points() const;
    ErrorNorms                   errors(const SidedField &exact,
                                        const std::function<std::array<double, 4>(geometry::Point, int)> &grad) const;
    std::vector<StressIntensity> stress_intensity_factors(double radius_factor) const;
    double                       strain_energy() const;
    /// Visits every quadrature point of the body (the cells' own quadratures, cut cells on their
    /// sub-triangles): its position, side of the first crack, u_h, grad u_h and JxW.
    void for_each_point(const std::function<void(const Point &x, int side, const dealii::Tensor<1, 2> &u,
                                                 const dealii::Tensor<2, 2> &grad, double JxW)> &visit) const;
    void                         write_vtu(const std::string &filename) const;

    dealii::Triangulation<2>  &tria;
    ElasticMaterial            material;
    EnrichmentSettings         settings;
    dealii::MappingQ1<2>       mapping;
    dealii::FE_Q<2>            fe;
    dealii::DoFHandler<2>      dof_handler;
    dealii::QGauss<2>          gauss, gauss_tip, gauss_far_tip;
    std::vector<Crack>         cracks;
    std::optional<Crack>       single_crack; ///< the crack when there is exactly one (crack())

    std::vector<Dirichlet>                                  dirichlet;
    std::vector<VertexDirichlet>                            vertex_dirichlet;
    std::vector<RegionDirichlet>                            region_dirichlet;
    std::vector<Traction>                                   tractions;
    std::vector<PointLoad>                                  point_loads;
    std::function<geometry::Point(geometry::Point)>         body_force;

    // Nodes: the scalar Q1 dofs that are not hanging. parents[s]: (node, weight) for dof s.
    std::vector<dealii::Point<2>>                           support;
    std::vector<std::vector<std::pair<unsigned int, double>>> parents;
    std::vector<unsigned int>                               nodes;
    std::vector<NodeKind>                                   kind; ///< tip if some block is a tip's
    std::vector<std::vector<NodeEnrichment>>                enrichment;
    std::vector<CellData>                                   cells;
    unsigned int                                            n_dofs = 0;

    /// Interpolation matrix of the prepared points (CSR, rows 2 i + c).
    struct PointMatrix
    {
      std::vector<unsigned int> row_start, column;
      std::vector<double>       value;
    } point_matrix;

    dealii::AffineConstraints<double> constraints;
    dealii::SparsityPattern           sparsity;
    dealii::SparseMatrix<double>      matrix;
    dealii::Vector<double>            rhs, solution;
  };

  /// Branch functions at x on the given side of the crack. Off the crack the level set decides
  /// and `side` agrees with it; on a face, the other side's values come from theta -> -theta,
  /// which flips F1 and F4 (odd in theta) and keeps F2 and F3.
  inline BranchValues branch_on_side(const Crack &crack, Point x, unsigned int tip, int side)
  {
    BranchValues b = crack.branch_functions(x, tip);
    if (crack.side(x) != side)
      for (int j : {0, 3})
        {
          b.value[j]    = -b.value[j];
          b.gradient[j] = -1. * b.gradient[j];
        }
    return b;
  }

  inline Point to_point(const dealii::Point<2> &p) { return {p[0], p[1]}; }
  inline dealii::Point<2> to_dealii(const Point &p) { return dealii::Point<2>(p.x, p.y); }
} // namespace pumpd::global
