// `cic transfer RUN... --robot R...`: each run's best genotype replayed
// unchanged on other robots (report/transfer.hpp), with eq. 7.1's terms and
// `cic assess`'s verdict. CSV, one row per (run, robot), the run's own robot
// first.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/io/xml.hpp"
#include "cic/report/gait_assessment.hpp"
#include "cic/report/plot.hpp"
#include "cic/report/transfer.hpp"
#include "cic/run/settings_lookup.hpp"

namespace cic::cli {

namespace {

// R0..R2, a robot file, or a shipped robot by name ("centipede-64" is
// settings/robots/centipede-64.xml wherever cic finds its settings).
report::TransferTarget target_named(const std::string& given) {
    report::TransferTarget t;
    if (given.size() == 2 && (given[0] == 'R' || given[0] == 'r') && given[1] >= '0' && given[1] <= '2') {
        t.preset = given[1] - '0';
        t.robot = io::load_robot(given, false);
        return t;
    }
    std::filesystem::path file(given);
    if (!std::filesystem::is_regular_file(file)) {
        const std::string shipped = "robots/" + (file.extension() == ".xml" ? given : given + ".xml");
        try {
            file = run::find_settings_file(shipped);
        } catch (const InputError&) {
            throw InputError("--robot " + given + ": not R0, R1, R2, a robot file, or a shipped robot (" + shipped +
                             ")");
        }
    }
    t.file = std::filesystem::absolute(file).lexically_normal().string();
    t.robot = io::read_robot_file(t.file);
    return t;
}

} // namespace

void add_transfer_command(Command& app, CommandContext& ctx) {
    struct Options {
        std::vector<std::string> inputs, robots;
        std::string out, offsets = "interpolate";
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand(
        "transfer", "Replay each run's best genotype unchanged on other robots: HyperGP's trees queried at the new "
                    "body's substrate, a direct gait tiled leg pair by leg pair. Eq. 7.1's terms and assess's verdict "
                    "per robot, and the share of the walk on the run's own robot. CSV (docs/transfer.md)");
    cmd.option("inputs", opts->inputs, "run folders, or study folders (their done runs)").required();
    cmd.option("--robot", opts->robots, "R0, R1, R2, a robot file or a shipped robot such as centipede-64 "
                                        "(repeatable)")
        .required();
    cmd.option("--offsets", opts->offsets, "Offset-HybrID's per-hinge offsets on another robot: interpolate (along "
                                           "the body, at the same place across it) or none (the trees alone)")
        .show_default();
    cmd.option("--out", opts->out, "write the CSV here (atomically) instead of stdout");
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "transfer", [&] {
            if (opts->offsets != "interpolate" && opts->offsets != "none")
                throw InputError("--offsets " + opts->offsets + ": allowed: interpolate, none");
            const auto rule = opts->offsets == "none" ? report::OffsetRule::None : report::OffsetRule::Interpolate;
            std::vector<report::TransferTarget> targets;
            for (const auto& r : opts->robots) targets.push_back(target_named(r));   // all checked before any replay
            const std::vector<std::string> inputs = report::finished_runs_of(opts->inputs);
            std::vector<report::TransferSource> sources;
            for (const auto& input : inputs) sources.push_back(report::read_transfer_source(input));
            std::ostringstream csv;
            csv << "run,genotype,from_robot,from_hinges,robot,hinges,rule,fitness,raw_fitness,distance,elevation,"
                   "verdict,share_of_own\n";
            for (const auto& src : sources) {
                report::TransferTarget own;
                own.robot = src.robot;
                own.file = src.robot_file;
                own.preset = src.settings.robot.robot_type;
                own.middle_legs = src.settings.neural.middle_legs;
                std::vector<report::TransferTarget> all{own};
                all.insert(all.end(), targets.begin(), targets.end());
                double own_raw = 0;
                for (std::size_t k = 0; k < all.size(); ++k) {
                    std::string how;
                    const report::ReplayItem item = report::replay_transferred(src, all[k], rule, 10.0, true, &how);
                    const report::GaitAssessment a = report::assess_gait(item);
                    if (k == 0) {
                        own_raw = a.raw_fitness;
                        how = "own";
                    }
                    const std::string share =
                        own_raw > 0 ? fmt::format("{:.4f}", a.raw_fitness / own_raw) : std::string();
                    csv << fmt::format("{},\"{}\",{},{},{},{},{},{:.17g},{:.17g},{:.4f},{:.4f},{},{}\n", src.run,
                                       src.what, src.robot.name, src.robot.actuated().size(), all[k].robot.name,
                                       all[k].robot.actuated().size(), how, a.fitness, a.raw_fitness, a.distance,
                                       a.elevation, a.verdict, share);
                }
            }
            if (opts->out.empty()) {
                std::cout << csv.str();
            } else {
                io::xml::write_file_atomically(opts->out, csv.str());
                if (!ctx.quiet)
                    std::cerr << fmt::format("transferred {} runs to {} robots; wrote {}\n", sources.size(),
                                             targets.size(), opts->out);
            }
            return 0;
        });
    });
}

} // namespace cic::cli
