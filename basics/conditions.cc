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

  std::vector<const Place *> places(const Conditions &conditions)
  {
    std::vector<const Place *> all;
    for (const auto &c : conditions.displacements)
      all.push_back(&c.place);
    for (const auto &c : conditions.tractions)
      all.push_back(&c.place);
    for (const auto &c : conditions.forces)
      all.push_back(&c.place);
    return all;
  }

  bool near_any(const Conditions &conditions, geometry::Point x, double radius)
  {
    const auto all = places(conditions);
    return std::any_of(all.begin(), all.end(), [&](const Place *place) { return near(*place, x, radius); });
  }
} // namespace pumpd::conditions
