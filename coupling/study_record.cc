#include "study_record.h"

#include <fstream>
#include <sstream>

#include "csv.h"
#include "hash.h"
#include "mesh.h"
#include "text.h"

namespace pumpd::coupling
{
  namespace
  {
    const char *header = "run,key,method,status,wall_s,peak_mib,pd_node_steps,global_dofs,pd_seconds";
  } // namespace

  std::string run_key(const std::string &program_version, const std::string &scene_text, const std::string &mesh_file)
  {
    const std::string sources = global::mesh_sources_hash(mesh_file);
    return hex(fnv1a(sources.empty() ? file_contents(mesh_file).value_or("") : sources,
                     fnv1a(scene_text, fnv1a(program_version))));
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
      records.push_back({r["run"], r["key"], r["method"], r["status"], csv_number(r["wall_s"]), csv_number(r["peak_mib"]),
                         csv_number(r["pd_node_steps"]), csv_number(r["global_dofs"]), csv_number(r["pd_seconds"])});
    return records;
  }

  void append_record(const std::string &file, const RunRecord &r)
  {
    CsvFile csv(file, header, true);
    csv.row(r.run, r.key, r.method, r.status, r.wall_seconds, r.peak_memory, r.pd_node_steps, r.global_dofs,
            r.pd_seconds);
  }
} // namespace pumpd::coupling
