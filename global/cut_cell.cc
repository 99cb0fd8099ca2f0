#include "cut_cell.h"

#include <deal.II/base/quadrature_lib.h>

#include <cmath>

namespace pumpd::global
{
  namespace
  {
    using Polygon = std::vector<RefPoint>;

    double cross(const dealii::Tensor<1, 2> &a, const dealii::Tensor<1, 2> &b) { return a[0] * b[1] - a[1] * b[0]; }

    /// Signed distance-like value of p from the line through a, b (positive on the left).
    double side_of(const RefPoint &p, const RefPoint &a, const RefPoint &b)
    {
      const dealii::Tensor<1, 2> d = b - a;
      return cross(d, p - a) / d.norm();
    }

    double area(const Polygon &poly)
    {
      double a = 0.;
      for (std::size_t i = 0; i < poly.size(); ++i)
        a += cross(dealii::Tensor<1, 2>(poly[i]), dealii::Tensor<1, 2>(poly[(i + 1) % poly.size()]));
      return 0.5 * a;
    }

    /// Part of a convex polygon on one side (sign +1 or -1) of the line a-b (Sutherland-Hodgman).
    Polygon clip(const Polygon &poly, const RefPoint &a, const RefPoint &b, double sign)
    {
      constexpr double eps = 1e-13;
      Polygon          out;
      for (std::size_t i = 0; i < poly.size(); ++i)
        {
          const RefPoint &p = poly[i], &q = poly[(i + 1) % poly.size()];
          const double    dp = sign * side_of(p, a, b), dq = sign * side_of(q, a, b);
          if (dp >= -eps)
            out.push_back(p);
          if ((dp > eps && dq < -eps) || (dp < -eps && dq > eps))
            out.push_back(p + (dp / (dp - dq)) * (q - p));
        }
      return out;
    }

    /// Splits every polygon the line a-b crosses into its two sides.
    std::vector<Polygon> split(const std::vector<Polygon> &polys, const RefPoint &a, const RefPoint &b)
    {
      std::vector<Polygon> out;
      for (const auto &poly : polys)
        {
          bool left = false, right = false;
          for (const auto &p : poly)
            {
              const double s = side_of(p, a, b);
              left |= s > 1e-13;
              right |= s < -1e-13;
            }
          if (!(left && right))
            {
              out.push_back(poly);
              continue;
            }
          for (double sign : {1., -1.})
            {
              Polygon part = clip(poly, a, b, sign);
              if (part.size() >= 3 && std::abs(area(part)) > 1e-14)
                out.push_back(std::move(part));
            }
        }
      return out;
    }

    /// True if p lies in the closed convex polygon.
    bool contains(const Polygon &poly, const RefPoint &p)
    {
      for (std::size_t i = 0; i < poly.size(); ++i)
        if (side_of(p, poly[i], poly[(i + 1) % poly.size()]) < -1e-12)
          return false;
      return true;
    }
  } // namespace

  std::vector<SubTriangle> subdivide_unit_square(const std::vector<std::array<RefPoint, 2>> &pieces,
                                                 const std::vector<RefPoint>               &tips)
  {
    std::vector<Polygon> polys = {{RefPoint(0, 0), RefPoint(1, 0), RefPoint(1, 1), RefPoint(0, 1)}};
    for (const auto &piece : pieces)
      if ((piece[1] - piece[0]).norm() > 1e-14)
        polys = split(polys, piece[0], piece[1]);

    std::vector<SubTriangle> triangles;
    for (const auto &poly : polys)
      {
        const RefPoint *tip = nullptr;
        for (const auto &t : tips)
          if (contains(poly, t))
            tip = &t;
        const auto add = [&](const RefPoint &a, const RefPoint &b, const RefPoint &c, bool singular) {
          if (std::abs(cross(b - a, c - a)) > 1e-14)
            triangles.push_back({{{a, b, c}}, singular});
        };
        for (std::size_t i = 0; i < poly.size(); ++i)
          {
            if (tip)
              add(*tip, poly[i], poly[(i + 1) % poly.size()], true);
            else if (i >= 1 && i + 1 < poly.size())
              add(poly[0], poly[i], poly[i + 1], false);
          }
      }
    return triangles;
  }

  dealii::Quadrature<2> sub_triangle_quadrature(const std::vector<SubTriangle> &triangles, unsigned int order,
                                                std::vector<unsigned int> &triangle_of_point)
  {
    // QGaussSimplex exists for 1 to 4 points per direction only; above that a collapsed Gauss
    // rule (Duffy with beta = 1, exact for polynomials on the triangle) takes its place.
    const dealii::QDuffy                  singular(order, 1.);
    const dealii::QSimplex<2>             regular = order <= 4 ? dealii::QSimplex<2>(dealii::QGaussSimplex<2>(order))
                                                               : dealii::QSimplex<2>(singular);
    std::vector<dealii::Point<2>>  points;
    std::vector<double>            weights;
    triangle_of_point.clear();
    for (unsigned int t = 0; t < triangles.size(); ++t)
      {
        const auto &tri  = triangles[t];
        const auto  rule = tri.singular ? singular.compute_affine_transformation(tri.vertex)
                                        : regular.compute_affine_transformation(tri.vertex);
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            points.push_back(rule.point(q));
            weights.push_back(rule.weight(q));
            triangle_of_point.push_back(t);
          }
      }
    return dealii::Quadrature<2>(points, weights);
  }
} // namespace pumpd::global
