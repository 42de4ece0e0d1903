// The rows of the settings table for the MapElites section (ours, beyond the
// thesis: docs/quality-diversity.md).
#include "settings_rows.hpp"

namespace cic::io::rows {

void map_elites_rows(std::vector<SettingKey>& t) {
    t.push_back(bool_row("MapElites", "enabled",
                         "Search with MAP-Elites (Mouret & Clune 2015) instead of the GP loop (hypergp) or the pagmo "
                         "optimiser (gait): a grid archive keeps the best solution of each behaviour cell. The GP "
                         "loop's population, selection, elitism, bloat control and Control.maximumIterations, and "
                         "the gait optimiser's Gait.optimizer, evaluations, populationSize, sigma0 and restarts, do "
                         "not apply; MapElites.evaluations is the budget",
                         FIELD(map_elites.enabled)));
    t.push_back(enum_row<sim::Descriptor>(
        "MapElites", "descriptor",
        {{sim::Descriptor::DutyFactor, {"duty-factor"}}, {sim::Descriptor::Omni, {"omni"}}},
        "The behaviour descriptor: duty-factor (the share of time each leg's end touches the ground, one dimension "
        "per leg; Cully et al. 2015) or omni (the centre's displacement on x and y, metres; QDax)",
        FIELD(map_elites.descriptor)));
    t.push_back(int_row("MapElites", "bins", 1, 1000,
                        "Cells per descriptor dimension (duty-factor: over [0, 1]; omni: over [-omniRange, "
                        "omniRange]); at most 10,000,000 cells in all",
                        FIELD(map_elites.bins)));
    t.push_back(double_row("MapElites", "omniRange", kPositive,
                           "omni: the grid spans [-omniRange, omniRange] metres on x and on y; a displacement past it "
                           "counts in the edge cell",
                           FIELD(map_elites.omni_range)));
    t.push_back(int_row("MapElites", "batch", 1, 100000,
                        "Solutions made and evaluated together (in the workers or MPI ranks) before the archive "
                        "takes them, in batch order",
                        FIELD(map_elites.batch)));
    t.push_back(int_row("MapElites", "initial", 1, 100000000,
                        "Solutions made from nothing (hypergp: the GP generator; gait: uniform points) before any "
                        "elite is varied",
                        FIELD(map_elites.initial)));
    t.push_back(detail::emitter_row());
    t.push_back(double_row("MapElites", "sigma", kPositive,
                           "gait: the standard deviation of the Gaussian mutation of an elite's parameters, in the "
                           "unit box where each parameter's range is 1 (iso-line: the isotropic part, sigma_iso; "
                           "Vassiliades & Mouret used 0.01; cma-me: the first step size of each CMA-ES start)",
                           FIELD(map_elites.sigma)));
    t.push_back(double_row("MapElites", "lineSigma", kNonNegative,
                           "iso-line: the standard deviation of the step along the line from one elite to a second "
                           "(sigma_line; Vassiliades & Mouret used 0.2)",
                           FIELD(map_elites.line_sigma)));
    t.back().digest_at_default = false;   // added after the first MAP-Elites runs
    t.push_back(long_row("MapElites", "evaluations", 1, 100000000,
                         "Budget of evaluations, whole batches only: the run stops before a batch that would pass it "
                         "(so a multiple of batch is spent exactly)",
                         FIELD(map_elites.evaluations)));
    t.push_back(double_row("MapElites", "qdOffset", kAnyFinite,
                           "The QD-score is the sum over the archive's elites of (fitness - qdOffset): choose it below "
                           "every fitness a run can reach (eq. 7.1 falls below 0 only by the height the centre loses)",
                           FIELD(map_elites.qd_offset)));
}

} // namespace cic::io::rows
