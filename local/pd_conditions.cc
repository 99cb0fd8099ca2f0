#include "pd_conditions.h"

namespace pumpd::local
{
  PrescribedRegion prescribed_region(const conditions::Place &place, bool fix_x, bool fix_y, double point_radius,
                                     double band_width)
  {
    switch (place.kind)
      {
        case conditions::Place::Kind::point:
          {
            std::vector<std::array<geometry::Point, 2>> at;
            for (const auto &x : place.points)
              at.push_back({x, x});
            return PrescribedRegion::band(place.name, at, point_radius, fix_x, fix_y);
          }
        case conditions::Place::Kind::boundary:
          return PrescribedRegion::band(place.name, place.edges, band_width, fix_x, fix_y);
        case conditions::Place::Kind::region:
          return PrescribedRegion::shape(place.name, place.box, place.inside, fix_x, fix_y);
      }
    return {};
  }
} // namespace pumpd::local
