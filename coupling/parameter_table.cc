#include "parameter_table.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "parameter_file.h"
#include "parameters.h"
#include "scene_lengths.h"
#include "text.h"

namespace pumpd::coupling
{
  namespace
  {
    std::string section_of(const std::string &path) { return path.substr(0, path.rfind('/') + 1); }
  } // namespace

  ParameterTable ParameterTable::of_file(const std::string &file)
  {
    Parameters               p;
    dealii::ParameterHandler prm;
    p.add_parameters(prm);
    auto set = parse_parameter_file(prm, file);
    return of_handler(prm, std::move(set));
  }

  ParameterTable ParameterTable::of_handler(const dealii::ParameterHandler &prm, std::set<std::string> set)
  {
    std::stringstream printed;
    prm.print_parameters(printed, dealii::ParameterHandler::ShortPRM);

    // The printed file, read back: "subsection <name>", "set <entry> = <value>", "end".
    ParameterTable           table;
    table.set_entries = std::move(set);
    std::vector<std::string> sections;
    std::string              line;
    while (std::getline(printed, line))
      {
        while (!line.empty() && line.back() == '\\')
          {
            std::string next;
            std::getline(printed, next);
            line = line.substr(0, line.size() - 1) + trim(next);
          }
        line = trim(line);
        if (line.rfind("subsection ", 0) == 0)
          sections.push_back(trim(line.substr(11)));
        else if (line == "end")
          sections.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            const auto  eq   = line.find('=');
            std::string path;
            for (const auto &s : sections)
              path += s + "/";
            table.entries.emplace_back(path + trim(line.substr(4, eq - 4)), trim(line.substr(eq + 1)));
          }
      }
    return table;
  }

  const std::string &ParameterTable::get(const std::string &path) const
  {
    for (const auto &[p, v] : entries)
      if (p == path)
        return v;
    throw std::out_of_range("no parameter " + path);
  }

  bool ParameterTable::has(const std::string &path) const
  {
    return std::any_of(entries.begin(), entries.end(), [&](const auto &e) { return e.first == path; });
  }

  void ParameterTable::set(const std::string &path, const std::string &value)
  {
    for (auto &[p, v] : entries)
      if (p == path)
        {
          v = value;
          set_entries.insert(path);
          return;
        }
    throw std::out_of_range("no parameter " + path);
  }

  std::vector<std::string> ParameterTable::find(const std::string &name, const std::vector<std::string> &sections) const
  {
    std::vector<std::string> found;
    for (const auto &[path, value] : entries)
      {
        const bool named   = path.size() > name.size() && path.compare(path.size() - name.size(), name.size(), name) == 0 &&
                           path[path.size() - name.size() - 1] == '/';
        const bool in_read = std::any_of(sections.begin(), sections.end(),
                                         [&](const auto &s) { return path.rfind(s + "/", 0) == 0; });
        if (named && in_read)
          found.push_back(path);
      }
    return found;
  }

  std::string ParameterTable::text(const std::string &omitted) const { return emit("", omitted + "/"); }

  std::string ParameterTable::section(const std::string &name) const { return emit(name + "/", "/"); }

  std::string ParameterTable::emit(const std::string &prefix, const std::string &omitted) const
  {
    std::ostringstream       out;
    std::vector<std::string> open; // the sections entered
    for (const auto &[path, value] : entries)
      {
        if (path.rfind(prefix, 0) != 0 || path.rfind(omitted, 0) == 0 || (is_scene_length(path) && !is_set(path)))
          continue;
        std::vector<std::string> wanted;
        std::stringstream        parts(section_of(path));
        for (std::string s; std::getline(parts, s, '/');)
          wanted.push_back(s);
        std::size_t common = 0;
        while (common < open.size() && common < wanted.size() && open[common] == wanted[common])
          ++common;
        for (; open.size() > common; open.pop_back())
          out << std::string(2 * (open.size() - 1), ' ') << "end\n";
        for (; open.size() < wanted.size(); open.push_back(wanted[open.size()]))
          out << std::string(2 * open.size(), ' ') << "subsection " << wanted[open.size()] << "\n";
        out << std::string(2 * open.size(), ' ') << "set " << path.substr(path.rfind('/') + 1) << " = " << value << "\n";
      }
    for (; !open.empty(); open.pop_back())
      out << std::string(2 * (open.size() - 1), ' ') << "end\n";
    return out.str();
  }
} // namespace pumpd::coupling
