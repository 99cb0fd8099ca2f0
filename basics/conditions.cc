#include "conditions.h"

#include <algorithm>

namespace pumpd::conditions
{
  bool near(const Place &place, geometry::Point x, double radius)
  {
    if (!place.box.contains(x, radius))
      return false;
    switch (place.kind)
      {
        case Place::Kind::boundary:
          for (const auto &[a, b] : place.edges)
            if (geometry::distance_to_segment(x, a, b) <= radius)
              return true;
          return false;
        case Place::Kind::point:
          for (const auto &p : place.points)
            if (geometry::norm(p - x) <= radius)
              return true;
          return false;
        case Place::Kind::region:
          return place.inside && place.inside(x);
      }
    return false;
  }

  bool near_any(const Conditions &conditions, geometry::Point x, double radius)
  {
    const auto at = [&](const auto &list) {
      return std::any_of(list.begin(), list.end(), [&](const auto &c) { return near(c.place, x, radius); });
    };
    return at(conditions.displacements) || at(conditions.tractions) || at(conditions.forces);
  }
} // namespace pumpd::conditions
