#pragma once
// `cic export RUN|STUDY...`: every individual of every saved generation as one
// CSV row, for pandas, R or a spreadsheet (docs/analysis.md):
//   run,config,seed,generation,id,fitness,distance,elevation,depth,size,failed,tree,cell,descriptor
// A study (a folder with index.csv) gives each of its runs, with the config and
// seed the index names. distance and elevation are eq. 7.1's terms, from a
// replay of each distinct genotype when asked (`terms`: one simulation each);
// empty otherwise and for symbolic regression. A gait run's individuals are
// its candidates: id is their place in the generation, tree their parameters.
// A MAP-Elites run (MapElites.enabled) gives the elites of its last archive:
// generation is the batch, id the cell's number, cell its bins "I,J,..." and
// descriptor the measured values; the two columns are empty for other runs.
// A run of a search registered from outside, whose checkpoints are files of its
// own (report::register_checkpoint_reader), gives per saved file the individual
// its reader names: its best, with id 0.
#include <filesystem>
#include <string>
#include <vector>

#include <functional>
#include <string>

namespace cic::report {

struct ExportRequest {
    std::vector<std::filesystem::path> inputs;   // run folders or study folders
    bool terms = false;                          // replay for distance and elevation
    // With terms: told when a run's champion (its last checkpoint's, verify.hpp)
    // does not replay to its stored fitness, one line naming the file and both values.
    std::function<void(const std::string&)> warn;
};

inline constexpr const char* kExportHeader =
    "run,config,seed,generation,id,fitness,distance,elevation,depth,size,failed,tree,cell,descriptor\n";

// The CSV text, header first. Throws cic::InputError naming the input for a
// folder that is neither a run (settings.xml and populations/) nor a study.
std::string export_individuals(const ExportRequest& request);

} // namespace cic::report
