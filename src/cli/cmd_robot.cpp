// `cic robot centipede`: write a generated robot file (sim/centipede.hpp), read
// back by the robot reader before it is kept.
#include <iostream>
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/io/xml.hpp"
#include "cic/sim/centipede.hpp"

namespace cic::cli {

void add_robot_command(Command& app, CommandContext& ctx) {
    struct Options {
        std::string kind;
        int pairs = 2;
        bool irregular = false;
        std::string out;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand(
        "robot", "Generate a robot file. `centipede`: a fixed torso along y with P pairs of R1's three-module legs "
                 "(hinges y, z, y), 8P-1 modules and 6P hinges; --irregular shortens the -x legs of the front "
                 "ceil(P/2) pairs by their tip module (docs/robots.md)");
    cmd.option("kind", opts->kind, "what to generate: centipede").required();
    cmd.option("--pairs", opts->pairs, "pairs of legs P").range(1, sim::max_centipede_pairs()).show_default();
    cmd.flag("--irregular", opts->irregular, "the irregular twin: the front ceil(P/2) -x legs a module shorter");
    cmd.option("--out", opts->out, "robot file to write (atomically)").required();
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "robot", [&] {
            if (opts->kind != "centipede")
                throw InputError("unknown robot kind '" + opts->kind + "' (allowed: centipede)");
            const sim::RobotSpec robot = sim::centipede(opts->pairs, opts->irregular);
            // The bytes to keep pass the reader first: what is written is a robot cic reads back.
            const std::string text = io::robot_to_xml(robot);
            const sim::RobotSpec back = io::parse_robot_xml(text, opts->out);
            if (back.modules.size() != robot.modules.size() || back.actuated() != robot.actuated())
                throw std::logic_error("the generated robot does not read back as written");
            io::xml::write_file_atomically(opts->out, text);
            if (!ctx.quiet)
                std::cerr << "wrote " << opts->out << ": " << robot.name << ", " << robot.modules.size()
                          << " modules, " << robot.actuated().size() << " hinges\n";
            return 0;
        });
    });
}

} // namespace cic::cli
