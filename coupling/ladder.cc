#include "ladder.h"

#include <algorithm>
#include <regex>
#include <sstream>

#include "error.h"
#include "text.h"

namespace pumpd::coupling
{
  namespace
  {
    std::vector<std::string> split(const std::string &s, char separator)
    {
      std::vector<std::string> parts;
      std::stringstream        in(s);
      for (std::string part; std::getline(in, part, separator);)
        parts.push_back(trim(part));
      return parts;
    }

    std::string joined(const std::vector<std::string> &parts)
    {
      std::string s;
      for (const auto &p : parts)
        s += (s.empty() ? "" : ", ") + p;
      return s;
    }

    /// The path of the override's entry among the sections `method` reads.
    std::string resolve(const ParameterTable &scene, const std::string &name, const std::string &method,
                        const std::string &entry, const std::string &rung)
    {
      if (name.find('/') != std::string::npos)
        {
          if (!scene.has(name))
            throw InvalidParameter(entry, rung, "no entry \"" + name + "\" in a scene file");
          return name;
        }
      const auto sections = sections_read_by(method);
      const auto found    = scene.find(name, sections);
      if (found.empty())
        throw InvalidParameter(entry, rung,
                               "no entry named \"" + name + "\" in the sections " + method + " reads (" +
                                 joined(sections) + "; see pumpd --print-parameters)");
      if (found.size() > 1)
        throw InvalidParameter(entry, rung,
                               "\"" + name + "\" is an entry of several sections (" + joined(found) +
                                 "): name one as <section>/<entry>");
      return found.front();
    }
  } // namespace

  std::vector<Override> parse_overrides(const std::string &overrides, const std::string &entry, const std::string &rung)
  {
    static const std::regex relative(R"((.*\S)\s+([x+-])\s*([-+]?[0-9.]+([eE][-+]?[0-9]+)?))");
    std::vector<Override>   result;
    if (trim(overrides).empty())
      return result;
    for (const auto &o : split(overrides, ','))
      {
        std::smatch m;
        if (const auto eq = o.find('='); eq != std::string::npos)
          result.push_back({trim(o.substr(0, eq)), '=', trim(o.substr(eq + 1))});
        else if (std::regex_match(o, m, relative))
          result.push_back({m[1], m[2].str()[0], m[3]});
        else
          throw InvalidParameter(entry, rung,
                                 "\"" + o + "\" is not an override: give <entry> = <value>, <entry> x <factor>, "
                                 "<entry> + <n> or <entry> - <n>");
        if (result.back().entry.empty())
          throw InvalidParameter(entry, rung, "\"" + o + "\" names no entry");
      }
    return result;
  }

  std::vector<Rung> parse_ladder(const std::string &ladder, const std::string &entry)
  {
    static const std::regex plain_name("[A-Za-z0-9._+-]+");
    std::vector<Rung>       rungs;
    for (const auto &r : split(ladder, ';'))
      {
        if (r.empty())
          continue;
        const auto colon = r.find(':');
        const auto name  = trim(r.substr(0, colon));
        if (colon == std::string::npos || !std::regex_match(name, plain_name))
          throw InvalidParameter(entry, r,
                                 "a rung is \"<name>: <override>, ...\", its name of letters, digits and . _ + - "
                                 "(the name of its files)");
        const auto setting = trim(r.substr(colon + 1));
        rungs.push_back({name, setting, parse_overrides(setting, entry, r)});
      }
    return rungs;
  }

  std::vector<std::string> sections_read_by(const std::string &method)
  {
    if (method == "lefm-growth")
      return {"Method", "Scene", "Global", "Crack growth", "LEFM growth"};
    if (method == "full-pd")
      return {"Method", "Scene", "Peridynamics", "Crack growth", "Full PD"};
    if (method == "pd-edge-crack")
      return {"Method", "Scene", "Peridynamics", "Edge crack"};
    return {"Method", "Scene", "Global", "Peridynamics", "Crack growth", "Global-local"};
  }

  ParameterTable apply(const ParameterTable &scene, const Rung &rung, const std::string &method,
                       const std::string &entry)
  {
    const std::string text = rung.name + ": " + rung.setting;
    ParameterTable    p    = scene;
    p.set("Method/Type", method);
    for (const auto &o : rung.overrides)
      if (o.entry == "Type" || o.entry == "Method/Type")
        p.set("Method/Type", o.value);
    for (const auto &o : rung.overrides)
      {
        const std::string path = resolve(p, o.entry, p.get("Method/Type"), entry, text);
        if (o.operation == '=')
          {
            p.set(path, o.value);
            continue;
          }
        double base = 0.;
        try
          {
            std::size_t used = 0;
            base             = std::stod(p.get(path), &used);
            if (used != p.get(path).size())
              throw std::invalid_argument("trailing text");
          }
        catch (const std::logic_error &)
          {
            throw InvalidParameter(entry, text,
                                   path + " = " + p.get(path) + " is not a number: only \"= <value>\" changes it");
          }
        const double by = std::stod(o.value);
        p.set(path, to_text(o.operation == 'x' ? base * by : o.operation == '+' ? base + by : base - by, 10));
      }
    return p;
  }
} // namespace pumpd::coupling
