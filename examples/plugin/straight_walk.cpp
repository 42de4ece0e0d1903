// A new experiment type built outside cic, against an installed cic
// (docs/extending.md): `straight`, HyperGP controllers scored by how far the
// robot walks along its preferred axis minus how far it drifts sideways, the
// drift weighed by a key of its own section, <StraightWalk> driftWeight.
//
// The file registers the type and hands the command line to cic's, so the
// program is a `cic` that knows one more type: runs, resumes, worker
// processes, sweeps, compare and plots all work as they do for `hypergp`.
#include <cmath>
#include <cstddef>

#include "cic/cli/cli.hpp"
#include "cic/experiments/hypergp/experiment.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/registry.hpp"
#include "cic/io/settings_extension.hpp"

namespace {

using namespace cic;

// Metres along the preferred axis minus driftWeight times metres across it,
// from the centre module's position at the delayed start and at the end.
double straight_fitness(const hypergp::Model& model, const io::Settings& settings, const hypergp::Outcome& o) {
    const std::size_t along = model.robot.preferred == sim::Axis::X ? 0 : 1;
    const std::size_t across = 1 - along;
    const double forward = std::fabs(o.result.end[along] - o.result.start[along]);
    const double drift = std::fabs(o.result.end[across] - o.result.start[across]);
    return forward - io::extra_number(settings, "StraightWalk", "driftWeight") * drift;
}

const experiments::Registrar registrar{{
    .type = {"straight", io::ExperimentFamily::HyperGP, "StraightWalk",
             "HyperGP scored by the distance along the preferred axis minus the weighted sideways drift"},
    .keys = {io::extra_number_key("StraightWalk", "driftWeight", 1.0, 0.0, 100.0,
                                  "Metres of forward walk that one metre of sideways drift costs")},
    .check_inputs = &hypergp::check_inputs,
    .make = [](const experiments::Context& ctx) { return experiments::make_hypergp_experiment(ctx, "straight"); },
    .job_kinds = {{"straight",
                   [](const experiments::WorkerContext& worker) {
                       return hypergp::make_job_handler([worker] { return worker.load_settings(); },
                                                        &straight_fitness);
                   }}},
}};

} // namespace

int main(int argc, char** argv) { return cic::cli::main(argc, argv); }
