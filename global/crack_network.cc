#include "crack_network.h"

#include <numeric>

namespace pumpd::global
{
  namespace
  {
    /// Union-find over the network's nodes: unite() is false if a and b were connected already.
    class Components
    {
    public:
      explicit Components(std::size_t n)
        : parent(n)
      {
        std::iota(parent.begin(), parent.end(), 0);
      }

      bool unite(std::size_t a, std::size_t b)
      {
        a = root(a);
        b = root(b);
        if (a == b)
          return false;
        parent[a] = b;
        return true;
      }

    private:
      std::size_t root(std::size_t a)
      {
        while (parent[a] != a)
          a = parent[a] = parent[parent[a]];
        return a;
      }

      std::vector<std::size_t> parent;
    };

    /// The crack nearest to p other than crack c.
    std::size_t nearest_other(const std::vector<Crack> &cracks, std::size_t c, Point p)
    {
      std::size_t best = c == 0 ? 1 : 0;
      for (std::size_t k = 0; k < cracks.size(); ++k)
        if (k != c && cracks[k].distance(p) < cracks[best].distance(p))
          best = k;
      return best;
    }
  } // namespace

  std::optional<std::size_t> boundary_curve(const geometry::Body &body, Point end, double tolerance, double hole_margin)
  {
    if (body.outline().distance(end) <= tolerance)
      return 0;
    std::optional<std::size_t> curve;
    for (std::size_t h = 0; h < body.holes().size(); ++h)
      if (body.holes()[h].distance(end) <= hole_margin + tolerance)
        curve = 1 + h;
    return curve;
  }

  std::string cut_through_message(const std::vector<Crack> &cracks)
  {
    return cracks.size() == 1 ? "the crack cut the body through" : "the cracks cut the body through";
  }

  bool cuts_off_a_piece(const std::vector<Crack> &cracks, const geometry::Body &body, double tolerance,
                        double hole_margin)
  {
    // Nodes: 0 the outline, 1 + h hole h, 1 + holes + c crack c.
    const std::size_t first_crack = 1 + body.holes().size();
    Components        network(first_crack + cracks.size());
    for (std::size_t c = 0; c < cracks.size(); ++c)
      {
        const auto &v = cracks[c].vertices();
        for (std::size_t e = 0; e < 2; ++e)
          {
            const Point end = e == 0 ? v.front() : v.back();
            std::size_t node;
            if (cracks[c].junctions()[e] && cracks.size() > 1)
              node = first_crack + nearest_other(cracks, c, end);
            else if (const auto curve = boundary_curve(body, end, tolerance, hole_margin))
              node = *curve;
            else
              continue; // a tip
            if (!network.unite(first_crack + c, node))
              return true;
          }
      }
    return false;
  }

  void join_touching(std::vector<Crack> &cracks, double tolerance)
  {
    for (std::size_t c = 0; c < cracks.size() && cracks.size() > 1; ++c)
      for (std::size_t t = cracks[c].tips().size(); t-- > 0;)
        {
          const Point       tip   = cracks[c].tips()[t].position;
          const std::size_t other = nearest_other(cracks, c, tip);
          if (cracks[other].distance(tip) <= tolerance)
            cracks[c].join(t, tip, cracks[other]);
        }
  }
} // namespace pumpd::global
