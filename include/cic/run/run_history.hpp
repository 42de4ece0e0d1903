#pragma once
// A run folder's history: its checkpoints (populations/gen-NNNN.xml, the
// latest also as population.xml) and stats.csv, one row per generation or
// batch. A resume goes on from the last checkpoint and never rewrites what
// came before it, so it first checks that the folder agrees with itself
// (docs/resume.md):
//   - population.xml is a regular file equal to the last gen-NNNN.xml; a run
//     stopped between the two writes (population.xml one checkpoint behind),
//     or one whose population.xml was lost, goes on from the last gen-NNNN.xml;
//   - the checkpoint's own number and evaluation counter are those of that
//     file's name and of stats.csv's row with that number.
// Each refusal is a cic::InputError (exit 2) naming the file and both values,
// thrown before anything is written.
#include <filesystem>
#include <optional>
#include <string>

#include "cic/search/search.hpp"

namespace cic::run {

struct ResumePoint {
    std::filesystem::path file;    // the checkpoint to go on from
    int number = -1;               // N of its populations/gen-NNNN.xml; -1: population.xml alone
    std::string note;              // for run.log and the console when it is not population.xml; empty otherwise
};

// The checkpoint a resume of `dir` goes on from; nullopt when the folder holds
// none (a run killed before its first checkpoint). Throws cic::InputError for
// a folder that cannot be read (a symbolic link loop, no permission), a
// population.xml that is not a regular file, or one that is not the last
// checkpoint.
std::optional<ResumePoint> resume_point(const std::filesystem::path& dir);

// Throws cic::InputError when the loaded checkpoint does not agree with its
// folder: its number is not its gen-NNNN.xml's, or stats.csv has no row of
// that number, or that row counts other evaluations.
void check_agrees_with_folder(const search::Checkpoint& c, const ResumePoint& at, const std::filesystem::path& dir);

// Removes what a process killed while writing left behind: FILE.tmp-PID and
// FILE.link-PID beside population.xml and in populations/ (never a file of
// the run's history). Call only once every check has passed.
void remove_stale_temporaries(const std::filesystem::path& dir);

} // namespace cic::run
