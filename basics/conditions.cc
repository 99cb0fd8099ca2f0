#include "conditions.h"

namespace pumpd::conditions
{
  bool reaches_into(const Place &place, const geometry::Box &box)
  {
    switch (place.kind)
      {
        case Place::Kind::boundary:
          for (const auto &[a, b] : place.edges)
            {
              if (box.contains(a) || box.contains(b))
                return true;
              const geometry::Point corners[4] = {
                {box.x_min, box.y_min}, {box.x_max, box.y_min}, {box.x_max, box.y_max}, {box.x_min, box.y_max}};
              for (int k = 0; k < 4; ++k)
                if (geometry::segments_intersect(a, b, corners[k], corners[(k + 1) % 4]))
                  return true;
            }
          return false;
        case Place::Kind::point:
          for (const auto &p : place.points)
            if (box.contains(p))
              return true;
          return false;
        case Place::Kind::region:
          return place.box.x_min <= box.x_max && box.x_min <= place.box.x_max && place.box.y_min <= box.y_max &&
                 box.y_min <= place.box.y_max;
      }
    return false;
  }

  std::vector<std::string> places_in(const Conditions &conditions, const geometry::Box &box)
  {
    std::vector<std::string> names;
    for (const auto &c : conditions.displacements)
      if (reaches_into(c.place, box))
        names.push_back(c.place.name);
    for (const auto &c : conditions.tractions)
      if (reaches_into(c.place, box))
        names.push_back(c.place.name);
    for (const auto &c : conditions.forces)
      if (reaches_into(c.place, box))
        names.push_back(c.place.name);
    return names;
  }
} // namespace pumpd::conditions
