#include "study_record.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "csv.h"
#include "text.h"

namespace pumpd::coupling
{
  namespace
  {
    const char *header = "run,key,method,status,wall_s,peak_mib,pd_node_steps,global_dofs,pd_seconds";

    /// FNV-1a over 8-byte words (the tail byte by byte): a change of any byte changes the hash
    /// but for chance collisions, at a word per multiplication (an executable of tens of MB).
    std::uint64_t fnv1a(const std::string &bytes, std::uint64_t h = 14695981039346656037ull)
    {
      const std::uint64_t prime = 1099511628211ull;
      std::size_t         i     = 0;
      for (; i + 8 <= bytes.size(); i += 8)
        {
          std::uint64_t word;
          std::memcpy(&word, bytes.data() + i, 8);
          h = (h ^ word) * prime;
        }
      for (; i < bytes.size(); ++i)
        h = (h ^ static_cast<unsigned char>(bytes[i])) * prime;
      return h;
    }

    std::string hex(std::uint64_t h)
    {
      std::ostringstream s;
      s << std::hex << std::setw(16) << std::setfill('0') << h;
      return s.str();
    }
  } // namespace

  std::string file_hash(const std::string &file)
  {
    const auto bytes = file_contents(file);
    return bytes ? hex(fnv1a(*bytes)) : "";
  }

  std::string run_key(const std::string &program_version, const std::string &scene_text, const std::string &mesh_file)
  {
    return hex(fnv1a(file_contents(mesh_file).value_or(""), fnv1a(scene_text, fnv1a(program_version))));
  }

  std::map<std::string, double> read_metrics(const std::string &log)
  {
    std::map<std::string, double> metrics;
    std::ifstream                 in(log);
    for (std::string line; std::getline(in, line);)
      {
        std::istringstream words(line);
        std::string        tag, name;
        double             value = 0.;
        if (words >> tag >> name >> value && tag == "pumpd-metric")
          metrics[name] = value;
      }
    return metrics;
  }

  std::vector<RunRecord> read_records(const std::string &file)
  {
    std::vector<RunRecord> records;
    for (auto &r : read_csv_rows(file))
      records.push_back({r["run"], r["key"], r["method"], r["status"], std::stod(r["wall_s"]), std::stod(r["peak_mib"]),
                         std::stod(r["pd_node_steps"]), std::stod(r["global_dofs"]), std::stod(r["pd_seconds"])});
    return records;
  }

  void append_record(const std::string &file, const RunRecord &r)
  {
    CsvFile csv(file, header, true);
    csv.row(r.run, r.key, r.method, r.status, r.wall_seconds, r.peak_memory, r.pd_node_steps, r.global_dofs,
            r.pd_seconds);
  }
} // namespace pumpd::coupling
