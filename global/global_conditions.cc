#include "global_conditions.h"

namespace pumpd::global
{
  using geometry::Point;

  void apply(const conditions::Conditions &conditions, EnrichedElasticity &problem, double lambda)
  {
    for (const auto &d : conditions.displacements)
      {
        const auto value = [d, lambda](Point x) {
          return Point{d.ux ? lambda * (*d.ux)(x) : 0., d.uy ? lambda * (*d.uy)(x) : 0.};
        };
        const bool fix_x = d.ux.has_value(), fix_y = d.uy.has_value();
        switch (d.place.kind)
          {
            case conditions::Place::Kind::boundary:
              problem.add_dirichlet(d.place.id, [value](Point x, int) { return value(x); }, fix_x, fix_y);
              break;
            case conditions::Place::Kind::point:
              for (const auto &x : d.place.points)
                problem.add_dirichlet_vertex(x, value(x), fix_x, fix_y);
              break;
            case conditions::Place::Kind::region:
              problem.add_dirichlet_region(d.place.id, value, fix_x, fix_y);
              break;
          }
      }
    for (const auto &t : conditions.tractions)
      problem.add_traction(t.place.id, [t, lambda](Point x, Point n) {
        const double p = t.p(x);
        return Point{lambda * (t.tx(x) - p * n.x), lambda * (t.ty(x) - p * n.y)};
      });
    for (const auto &f : conditions.forces)
      for (const auto &x : f.place.points)
        problem.add_point_load(x, (lambda / double(f.place.points.size())) * f.force);
  }
} // namespace pumpd::global
