// `cic render`: POV-Ray scenes of a replayed individual, one per video frame.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/cli/replay_options.hpp"
#include "cic/io/povray.hpp"

namespace cic::app {

void add_render_command(Command& app, CommandContext& ctx) {
    struct Options {
        ReplaySource source;
        std::string out;
        double fps = 25.0;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand(
        "render", "Write POV-Ray scenes (one per frame) of an individual's replay; "
                  "scripts/render-video.sh DIR turns them into an MP4");
    add_replay_options(cmd, opts->source);
    cmd.option("--out", opts->out, "folder for frame_NNNNN.pov and the shared includes").required();
    cmd.option("--fps", opts->fps, "frames per second of the video").show_default().positive();
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "render", [&] {
            const auto items = load_replay(opts->source, 1, opts->fps, false);
            const ReplayItem& item = items.at(0);
            io::PovrayOptions pov;
            pov.centre_body = item.centre_body;
            pov.title = item.label;
            const int frames = io::write_povray(item.recording, opts->out, opts->fps, pov);
            if (!ctx.quiet)
                std::cerr << fmt::format("{}: fitness {:.6g}; wrote {} frames to {}\n"
                                         "render the video with: scripts/render-video.sh {} --fps {:g}\n",
                                         item.label, item.replayed_fitness, frames, opts->out, opts->out, opts->fps);
            return 0;
        });
    });
}

} // namespace cic::app
