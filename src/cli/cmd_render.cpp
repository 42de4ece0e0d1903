// `cic render`: POV-Ray scenes of a replayed individual, one per video frame.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/cli/replay_options.hpp"
#include "cic/core/error.hpp"
#include "cic/io/povray.hpp"

namespace cic::cli {

void add_render_command(Command& app, CommandContext& ctx) {
    struct Options {
        report::ReplaySource source;
        std::string out;
        double fps = 25.0;
        bool no_trail = false;
        std::string camera = "follow";
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand(
        "render", "Write POV-Ray scenes (one per frame) of an individual's replay; "
                  "scripts/render-video.sh DIR turns them into an MP4");
    add_replay_options(cmd, opts->source);
    cmd.option("--out", opts->out, "folder for frame_NNNNN.pov and the shared includes").required();
    cmd.option("--fps", opts->fps, "frames per second of the video").show_default().positive();
    cmd.flag("--no-trail", opts->no_trail,
             "draw no trail (default: the centre's path so far on the ground, a green ring at its start)");
    cmd.option("--camera", opts->camera, "follow (the robot's centre) or fixed (on the world, framing the whole path)")
        .show_default();
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "render", [&] {
            if (opts->camera != "follow" && opts->camera != "fixed")
                throw InputError("--camera takes follow or fixed; got '" + opts->camera + "'");
            const auto items = report::load_replay(opts->source, 1, opts->fps, false);
            const report::ReplayItem& item = items.at(0);
            io::PovrayOptions pov;
            pov.centre_body = item.centre_body;
            pov.title = item.label;
            pov.trail = !opts->no_trail;
            pov.fixed_camera = opts->camera == "fixed";
            const int frames = io::write_povray(item.recording, opts->out, opts->fps, pov);
            if (!ctx.quiet)
                std::cerr << fmt::format("{}: fitness {:.6g}; wrote {} frames to {}\n"
                                         "render the video with: scripts/render-video.sh {} --fps {:g}\n",
                                         item.label, item.replayed_fitness, frames, opts->out, opts->out, opts->fps);
            return 0;
        });
    });
}

} // namespace cic::cli
